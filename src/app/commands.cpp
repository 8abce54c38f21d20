#include "app/commands.hpp"

#include <omp.h>

#include <cstdio>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "app/checkpoint_match.hpp"
#include "app/child_process.hpp"
#include "app/console_monitor.hpp"
#include "app/interrupt.hpp"
#include "app/method_outputs.hpp"
#include "app/output_folder.hpp"
#include "app/preflight.hpp"
#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "app/tools_dir.hpp"
#include "core/error.hpp"
#include "io/case.hpp"
#include "io/checkpoint_folder.hpp"

namespace partimix::app {
namespace {

void print_parameters(const Simulation& simulation, const io::Case& the_case) {
  for (std::size_t m = 0; m < simulation.methods.size(); ++m) {
    if (!the_case.single_method())
      fmt::print(stderr, "  {}:\n", the_case.methods[m].name);
    for (const auto& [name, value] : simulation.methods[m].solver->derived_parameters())
      fmt::print(stderr, "  {:<24} {:.6g}\n", name, value);
  }
  for (std::size_t k = 0; k < simulation.couplings.size(); ++k) {
    fmt::print(stderr, "  couplings[{}]:\n", k);
    for (const auto& [name, value] : simulation.couplings[k]->derived_parameters())
      fmt::print(stderr, "  {:<24} {:.6g}\n", name, value);
  }
}

void print_warnings(const Simulation& simulation) {
  for (const std::string& warning : simulation.warnings)
    fmt::print(stderr, "warning: {}\n", warning);
}

// The figures with their units; one with a caveat is marked and the reasons follow, once each.
void print_figures(const Runner& runner) {
  const analysis::Caveats& caveats = runner.caveats();
  std::map<std::string, std::vector<std::string>> reasons;
  for (const auto& [name, value] : runner.figures()) {
    const auto caveat = caveats.find(name);
    const bool marked = caveat != caveats.end();
    const std::string& unit = runner.figure_units().at(name);
    fmt::print(stderr, "  {:<32} {:.6g}{}\n",
               fmt::format("{} [{}]", name, unit.empty() ? "-" : unit), value,
               marked ? "  (unreliable, see below)" : "");
    if (marked)
      reasons[caveat->second].push_back(name);
  }
  for (const auto& [reason, names] : reasons)
    fmt::print(stderr, "warning: {}: {}\n", fmt::join(names, ", "), reason);
}

// The throughput is this process's: a resumed run's totals include the processes before it.
void print_summary(const io::RunSummary& summary) {
  const double throughput = summary.process_wall_seconds > 0.0
                                ? static_cast<double>(summary.particles * summary.process_steps) /
                                      summary.process_wall_seconds
                                : 0.0;
  const bool resumed = summary.process_steps != summary.steps;
  fmt::print(stderr, "{}: {} steps to t = {:.6g} s in {:.1f} s ({:.3g} particle-steps/s{})\n",
             summary.status, summary.steps, summary.simulated_time, summary.wall_seconds,
             throughput, resumed ? " in this process" : "");
  if (!summary.message.empty())
    fmt::print(stderr, "{}\n", summary.message);
}

void print_estimate(const RunEstimate& estimate) {
  fmt::print(stderr, "  {:<24} {:.6g}\n", "first_time_step [s]", estimate.first_dt);
  fmt::print(stderr, "  {:<24} {:.3g}\n", "steps (estimate)", estimate.steps);
  fmt::print(stderr, "  {:<24} {:.3g}\n", "series rows", estimate.series_rows);
  fmt::print(stderr, "  {:<24} {:.3g}\n", "frames", estimate.frames);
}

int exit_code_of(const std::string& status) {
  if (status == "completed")
    return kExitSuccess;
  if (status == "interrupted")
    return kExitInterrupted;
  return kExitRunFailed;
}

struct Checkpoint {
  StateArchive state;
  std::filesystem::path file;
};

// The checkpoint to resume from: the newest readable one in the folder, of this case.
std::optional<Checkpoint> checkpoint_to_resume(const RunArguments& arguments,
                                               const io::Case& the_case) {
  if (arguments.resume_dir.empty())
    return std::nullopt;
  const io::CheckpointFolder folder(arguments.resume_dir / "checkpoints");
  Checkpoint checkpoint;
  checkpoint.state = folder.read_latest(&checkpoint.file);
  check_checkpoint_matches(the_case, checkpoint.state, checkpoint.file);
  folder.remove_newer_than(checkpoint.file);
  fmt::print(stderr, "resuming from {}\n", checkpoint.file.string());
  return checkpoint;
}

std::filesystem::path output_dir_of(const RunArguments& arguments, const io::Case& the_case) {
  if (!arguments.resume_dir.empty())
    return arguments.resume_dir;
  if (!arguments.output_dir.empty())
    return arguments.output_dir;
  return std::filesystem::path("out") / the_case.name;
}

}  // namespace

int run_command(const RunArguments& arguments) {
  install_interrupt_handler();
  ConsoleMonitor monitor(stderr);
  try {
    // Before the simulation is built: its fill and settling run on these threads too.
    if (arguments.threads > 0)
      omp_set_num_threads(arguments.threads);
    const io::Case the_case = io::load_case(arguments.case_file, arguments.overrides);
    RunOptions options;
    options.threads = omp_get_max_threads();
    options.output_dir = output_dir_of(arguments, the_case);
    options.overwrite = arguments.overwrite;
    if (arguments.resume_dir.empty())
      check_output_folder(options.output_dir, options.overwrite);
    const std::optional<Checkpoint> checkpoint = checkpoint_to_resume(arguments, the_case);
    Simulation simulation =
        build_simulation(the_case, {checkpoint.has_value(), arguments.quiet ? nullptr : &monitor});
    monitor.finish();
    print_warnings(simulation);
    estimate_run(the_case, simulation);
    options.show_progress = !arguments.quiet;
    Runner runner(the_case, simulation, options);
    fmt::print(stderr, "partimix {}: {} ({} particles, {} threads) -> {}\n", PARTIMIX_VERSION,
               the_case.name, simulation.particle_count(), options.threads,
               options.output_dir.string());
    print_parameters(simulation, the_case);
    io::RunSummary summary;
    try {
      summary = runner.run(checkpoint ? &checkpoint->state : nullptr);
    } catch (const StateError& error) {
      throw InputError(InputLocation{checkpoint->file.string(), 0, 0, ""},
                       fmt::format("the checkpoint does not fit the case: {}", error.what()));
    }
    print_summary(summary);
    print_figures(runner);
    return exit_code_of(summary.status);
  } catch (const InputError& error) {
    monitor.finish();
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  } catch (const RunError& error) {
    fmt::print(stderr, "run failed: {}\n", error.what());
    return kExitRunFailed;
  } catch (const Interrupted& error) {
    monitor.finish();
    fmt::print(stderr, "{}; nothing was written\n", error.what());
    return kExitInterrupted;
  }
}

// Loads and builds the case as `run` would (settling grains included), checks its analyses
// and output columns, estimates the run and takes its first step; writes nothing.
int check_command(const std::string& case_file, const std::vector<std::string>& overrides) {
  install_interrupt_handler();
  ConsoleMonitor monitor(stderr);
  try {
    const io::Case the_case = io::load_case(case_file, overrides);
    Simulation simulation = build_simulation(the_case, {false, &monitor});
    monitor.finish();
    print_warnings(simulation);
    for (std::size_t m = 0; m < simulation.methods.size(); ++m)
      MethodOutputs(the_case, m, simulation.methods[m]);
    const RunEstimate estimate = estimate_run(the_case, simulation);
    take_first_step(the_case, simulation, estimate.first_dt);
    fmt::print(stderr, "{}: valid ({} particles)\n", case_file, simulation.particle_count());
    print_parameters(simulation, the_case);
    print_estimate(estimate);
    return kExitSuccess;
  } catch (const InputError& error) {
    monitor.finish();
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  } catch (const Interrupted& error) {
    monitor.finish();
    fmt::print(stderr, "{}\n", error.what());
    return kExitInterrupted;
  }
}

// The plot script is started with an argument vector, never through a shell: the folder's name
// reaches it as one argument whatever characters it holds.
int plot_command(const std::filesystem::path& output_dir) {
  const std::filesystem::path script = tools_dir() / "plot_series.py";
  try {
    return wait_process(start_process({"/usr/bin/python3", script.string(), output_dir.string()}));
  } catch (const RunError& error) {
    fmt::print(stderr, "plot failed: {}\n", error.what());
    return kExitRunFailed;
  }
}

}  // namespace partimix::app
