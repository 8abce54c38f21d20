#include "app/commands.hpp"

#include <omp.h>

#include <cstdio>
#include <cstdlib>

#include <sys/wait.h>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "app/interrupt.hpp"
#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "app/tools_dir.hpp"
#include "core/error.hpp"
#include "io/case.hpp"

namespace partimix::app {
namespace {

void print_parameters(const Solver& solver) {
  for (const auto& [name, value] : solver.derived_parameters()) {
    fmt::print(stderr, "  {:<24} {:.6g}\n", name, value);
  }
}

void print_warnings(const Simulation& simulation) {
  for (const std::string& warning : simulation.warnings)
    fmt::print(stderr, "warning: {}\n", warning);
}

void print_figures(const std::map<std::string, double>& figures) {
  for (const auto& [name, value] : figures)
    fmt::print(stderr, "  {:<24} {:.6g}\n", name, value);
}

int exit_code_of(const std::string& status) {
  if (status == "completed")
    return kExitSuccess;
  if (status == "interrupted")
    return kExitInterrupted;
  return kExitRunFailed;
}

}  // namespace

int run_command(const RunArguments& arguments) {
  try {
    const io::Case the_case = io::load_case(arguments.case_file, arguments.overrides);
    Simulation simulation = build_simulation(the_case);
    print_warnings(simulation);
    if (arguments.threads > 0)
      omp_set_num_threads(arguments.threads);
    RunOptions options;
    options.output_dir = arguments.output_dir.empty() ? std::filesystem::path("out") / the_case.name
                                                      : arguments.output_dir;
    options.threads = omp_get_max_threads();
    options.show_progress = !arguments.quiet;
    fmt::print(stderr, "partimix {}: {} ({} particles, {} threads) -> {}\n", PARTIMIX_VERSION,
               the_case.name, simulation.store->size(), options.threads,
               options.output_dir.string());
    print_parameters(*simulation.solver);
    install_interrupt_handler();
    Runner runner(the_case, *simulation.solver, simulation.bodies.get(), options);
    const io::RunSummary summary = runner.run();
    const double throughput =
        summary.wall_seconds > 0.0
            ? static_cast<double>(summary.particles * summary.steps) / summary.wall_seconds
            : 0.0;
    fmt::print(stderr, "{}: {} steps to t = {:.6g} s in {:.1f} s ({:.3g} particle-steps/s)\n",
               summary.status, summary.steps, summary.simulated_time, summary.wall_seconds,
               throughput);
    if (!summary.message.empty())
      fmt::print(stderr, "{}\n", summary.message);
    print_figures(runner.figures());
    return exit_code_of(summary.status);
  } catch (const InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  } catch (const RunError& error) {
    fmt::print(stderr, "run failed: {}\n", error.what());
    return kExitRunFailed;
  }
}

int check_command(const std::string& case_file, const std::vector<std::string>& overrides) {
  try {
    const io::Case the_case = io::load_case(case_file, overrides);
    const Simulation simulation = build_simulation(the_case);
    print_warnings(simulation);
    fmt::print(stderr, "{}: valid ({} particles)\n", case_file, simulation.store->size());
    print_parameters(*simulation.solver);
    return kExitSuccess;
  } catch (const InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  }
}

int plot_command(const std::filesystem::path& output_dir) {
  const std::filesystem::path script = tools_dir() / "plot_series.py";
  const std::string command =
      fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), output_dir.string());
  const int status = std::system(command.c_str());
  if (status == -1)
    return kExitRunFailed;
  return WEXITSTATUS(status);
}

}  // namespace partimix::app
