// partimix: run, check, sweep and plot particle simulations of mixing (README.md).
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "app/optimise.hpp"
#include "app/sweep.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  using namespace partimix;
  CLI::App cli{"partimix: particle methods for mixing and granular processes"};
  cli.set_version_flag("--version", std::string("partimix ") + PARTIMIX_VERSION);
  cli.require_subcommand(1);

  app::RunArguments run;
  CLI::App* run_cmd = cli.add_subcommand("run", "Run a case and write its outputs");
  run_cmd->add_option("case", run.case_file, "Case file (YAML)")->required();
  run_cmd->add_option("--out,-o", run.output_dir, "Output folder (default: out/<case name>)");
  run_cmd->add_option("--set,-s", run.overrides, "Override a case key: key.path=value");
  run_cmd->add_option("--threads,-t", run.threads, "OpenMP threads (default: all cores)")
      ->check(CLI::Range(1, 4096));
  run_cmd->add_flag("--quiet,-q", run.quiet, "No progress line");
  run_cmd->add_flag("--overwrite", run.overwrite,
                    "Write into an output folder that holds files partimix did not write");
  run_cmd
      ->add_option("--resume", run.resume_dir,
                   "Resume the run in this output folder from its newest checkpoint")
      ->excludes("--out");

  std::string check_file;
  std::vector<std::string> check_overrides;
  CLI::App* check_cmd = cli.add_subcommand("check", "Validate a case file and report its set-up");
  check_cmd->add_option("case", check_file, "Case file (YAML)")->required();
  check_cmd->add_option("--set,-s", check_overrides, "Override a case key: key.path=value");

  app::SweepArguments sweep;
  CLI::App* sweep_cmd =
      cli.add_subcommand("sweep", "Run a case for every combination of varied keys; one table");
  sweep_cmd->add_option("case", sweep.case_file, "Case file (YAML)")->required();
  sweep_cmd->add_option("--vary", sweep.varied, "Vary a case key: key.path=v1,v2,...")->required();
  sweep_cmd->add_option("--set,-s", sweep.overrides, "Override a case key in every run");
  sweep_cmd->add_option("--out,-o", sweep.output_dir, "Sweep folder (default: out/<name>_sweep)");
  sweep_cmd->add_option("--jobs,-j", sweep.jobs, "Runs at a time (default: 1)")
      ->check(CLI::Range(1, 4096));
  sweep_cmd->add_option("--threads,-t", sweep.threads, "Threads per run (default: cores / jobs)")
      ->check(CLI::Range(1, 4096));
  sweep_cmd->add_flag("--overwrite", sweep.overwrite,
                      "Write into a sweep folder that holds files partimix did not write");

  std::string plot_dir;
  CLI::App* plot_cmd = cli.add_subcommand("plot", "Plot series.csv of an output folder to PNG");
  plot_cmd->add_option("outdir", plot_dir, "Output folder of a run")->required();

  app::OptimiseArguments optimise;
  CLI::App* optimise_cmd = cli.add_subcommand(
      "optimise", "Search case keys within bounds for the design that minimises a figure");
  optimise_cmd->add_option("case", optimise.case_file, "Case file (YAML)")->required();
  optimise_cmd->add_option("--vary", optimise.varied, "A key and its bounds: key.path=lo:hi")
      ->required();
  optimise_cmd->add_option("--minimise", optimise.figure, "The run.json figure to minimise")
      ->required();
  optimise_cmd->add_option("--target", optimise.target, "Stop once the figure is at or below it");
  optimise_cmd->add_option("--algorithm", optimise.algorithm,
                           "bobyqa (default), cobyla or neldermead (NLopt)");
  optimise_cmd->add_option("--evaluations", optimise.evaluations, "Most runs (default: 20)")
      ->check(CLI::Range(1, 10000));
  optimise_cmd->add_option("--set,-s", optimise.overrides, "Override a case key in every run");
  optimise_cmd->add_option("--out,-o", optimise.output_dir,
                           "Search folder (default: out/<name>_optimise); again to resume");
  optimise_cmd->add_option("--threads,-t", optimise.threads, "Threads per run (default: all)")
      ->check(CLI::Range(1, 4096));

  std::string stl_file;
  std::vector<std::string> stl_overrides;
  std::string stl_dir = ".";
  CLI::App* stl_cmd =
      cli.add_subcommand("stl", "Write the walls generated as meshes (truck_drum) as STL files");
  stl_cmd->add_option("case", stl_file, "Case file (YAML)")->required();
  stl_cmd->add_option("--set,-s", stl_overrides, "Override a case key: key.path=value");
  stl_cmd->add_option("--out,-o", stl_dir, "Folder for wall_<k>.stl (default: .)");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = cli.exit(error);
    return code == 0 ? kExitSuccess : kExitBadInput;
  }
  if (run_cmd->parsed())
    return app::run_command(run);
  if (check_cmd->parsed())
    return app::check_command(check_file, check_overrides);
  if (sweep_cmd->parsed())
    return app::sweep_command(sweep);
  if (optimise_cmd->parsed())
    return app::optimise_command(optimise);
  if (stl_cmd->parsed())
    return app::stl_command(stl_file, stl_overrides, stl_dir);
  return app::plot_command(plot_dir);
}
