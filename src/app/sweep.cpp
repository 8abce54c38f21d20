#include "app/sweep.hpp"

#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/interrupt.hpp"
#include "app/output_folder.hpp"
#include "app/run_pool.hpp"
#include "app/sweep_plan.hpp"
#include "app/sweep_plot.hpp"
#include "app/sweep_table.hpp"
#include "core/error.hpp"
#include "io/case.hpp"

namespace partimix::app {
namespace {

namespace fs = std::filesystem;

struct Sweep {
  std::vector<SweepAxis> axes;
  std::vector<SweepPoint> points;
  fs::path dir;
};

std::string run_name(std::size_t index) {
  return fmt::format("run_{:03d}", index);
}

std::string describe(const Sweep& sweep, std::size_t index) {
  return fmt::format("{}", fmt::join(point_overrides(sweep.axes, sweep.points[index]), " "));
}

// The fixed overrides, then one per axis, so that a varied key wins.
std::vector<std::string> run_overrides(const SweepArguments& arguments,
                                       const std::vector<SweepAxis>& axes,
                                       const SweepPoint& point) {
  std::vector<std::string> overrides = arguments.overrides;
  const std::vector<std::string> varied = point_overrides(axes, point);
  overrides.insert(overrides.end(), varied.begin(), varied.end());
  return overrides;
}

bool is_varied(const std::vector<SweepAxis>& axes, const std::string& key_path) {
  return std::any_of(axes.begin(), axes.end(), [&](const SweepAxis& axis) {
    return key_path == axis.key || key_path.starts_with(axis.key + ".") ||
           key_path.starts_with(axis.key + "[");
  });
}

// `error` from loading the case of `point`, naming --vary when a varied key is at fault, and
// the combination.
InputError in_combination(const InputError& error, const std::vector<SweepAxis>& axes,
                          const SweepPoint& point) {
  InputLocation where = error.location();
  if (where.file == "--set" && is_varied(axes, where.key_path))
    where.file = "--vary";
  return InputError(where, fmt::format("{} (in the run with {})", error.message(),
                                       fmt::join(point_overrides(axes, point), " ")));
}

// Loads and validates the case of every point (io::load_case, without building the particles);
// returns the case name.
std::string validate_points(const SweepArguments& arguments, const Sweep& sweep) {
  std::string name;
  for (const SweepPoint& point : sweep.points) {
    try {
      const io::Case the_case =
          io::load_case(arguments.case_file, run_overrides(arguments, sweep.axes, point));
      name = the_case.name;
    } catch (const InputError& error) {
      throw in_combination(error, sweep.axes, point);
    }
  }
  return name;
}

Sweep plan_sweep(const SweepArguments& arguments) {
  Sweep sweep;
  sweep.axes = parse_sweep_axes(arguments.varied);
  sweep.points = sweep_points(sweep.axes);
  const std::string name = validate_points(arguments, sweep);
  sweep.dir =
      arguments.output_dir.empty() ? fs::path("out") / (name + "_sweep") : arguments.output_dir;
  return sweep;
}

int threads_per_run(const SweepArguments& arguments) {
  if (arguments.threads > 0)
    return arguments.threads;
  return std::max(1, omp_get_num_procs() / std::max(1, arguments.jobs));
}

PoolTask run_task(const SweepArguments& arguments, const Sweep& sweep, std::size_t index) {
  const fs::path run_dir = sweep.dir / run_name(index);
  std::error_code error;
  fs::create_directories(run_dir, error);
  if (error)
    throw RunError(fmt::format("cannot create {}: {}", run_dir.string(), error.message()));
  record_output(sweep.dir, run_name(index));
  record_output(sweep.dir, run_name(index) + "/log.txt");
  std::vector<std::string> argv{"/proc/self/exe", "run", arguments.case_file};
  for (const std::string& text : run_overrides(arguments, sweep.axes, sweep.points[index])) {
    argv.push_back("--set");
    argv.push_back(text);
  }
  const std::string threads = std::to_string(threads_per_run(arguments));
  // --overwrite: the run's folder holds the log the sweep writes, which the run must keep.
  argv.insert(argv.end(),
              {"--out", run_dir.string(), "--overwrite", "--quiet", "--threads", threads});
  return {argv, run_dir / "log.txt"};
}

void report_end(const Sweep& sweep, std::size_t index, int exit_code) {
  const RunRecord record = read_run_record(sweep.dir / run_name(index));
  fmt::print(stderr, "{} ({}): {}", run_name(index), describe(sweep, index), record.status);
  if (exit_code != kExitSuccess)
    fmt::print(stderr, " (exit code {}; see {})", exit_code,
               (sweep.dir / run_name(index) / "log.txt").string());
  fmt::print(stderr, "\n");
}

std::vector<std::optional<int>> run_all(const SweepArguments& arguments, const Sweep& sweep) {
  prepare_output_folder(sweep.dir, arguments.overwrite);
  record_output(sweep.dir, "sweep.csv");
  record_output(sweep.dir, "np_re.png");
  std::vector<PoolTask> tasks;
  for (std::size_t i = 0; i < sweep.points.size(); ++i)
    tasks.push_back(run_task(arguments, sweep, i));
  fmt::print(stderr, "partimix sweep: {} runs of {}, {} at a time, {} threads each -> {}\n",
             tasks.size(), arguments.case_file, std::max(1, arguments.jobs),
             threads_per_run(arguments), sweep.dir.string());
  install_interrupt_handler();
  return run_pool(tasks, arguments.jobs,
                  [&](std::size_t index, int exit_code) { report_end(sweep, index, exit_code); });
}

SweepTable gather(const Sweep& sweep, const std::vector<std::optional<int>>& codes) {
  SweepTable table;
  for (const SweepAxis& axis : sweep.axes)
    table.keys.push_back(axis.key);
  for (std::size_t i = 0; i < sweep.points.size(); ++i) {
    const RunRecord record =
        codes[i] ? read_run_record(sweep.dir / run_name(i)) : RunRecord{"skipped", {}, {}, {}};
    table.rows.push_back({run_name(i), sweep.points[i], record});
  }
  return table;
}

int exit_code_of(const SweepTable& table, const std::vector<std::optional<int>>& codes) {
  if (interrupt_requested())
    return kExitInterrupted;
  const bool all_completed =
      std::all_of(codes.begin(), codes.end(), [](const auto& code) { return code == 0; }) &&
      std::all_of(table.rows.begin(), table.rows.end(),
                  [](const SweepRow& row) { return row.record.status == "completed"; });
  return all_completed ? kExitSuccess : kExitRunFailed;
}

// The Np-Re fit takes every run's Np and Re: say which of them carry a caveat (an average not
// over a full window, a body the fluid sees through), so that a slope of such runs is not read
// as a result.
void warn_of_unreliable_fit(const SweepTable& table) {
  for (const SweepRow& row : table.rows) {
    for (const char* figure : {"Np", "Re"}) {
      const auto caveat = row.record.caveats.find(figure);
      if (caveat != row.record.caveats.end())
        fmt::print(stderr, "warning: the Np-Re fit uses {} of {}, which is unreliable: {}\n",
                   figure, row.run, caveat->second);
    }
  }
}

void write_results(const Sweep& sweep, const SweepTable& table) {
  write_sweep_csv(sweep.dir / "sweep.csv", table);
  fmt::print(stderr, "\n");
  print_sweep_table(stderr, table);
  fmt::print(stderr, "table: {}\n", (sweep.dir / "sweep.csv").string());
  if (!can_plot_np_re(table))
    return;
  warn_of_unreliable_fit(table);
  if (plot_np_re(sweep.dir) != kExitSuccess)
    fmt::print(stderr, "warning: the Np-Re plot failed (tools/plot_sweep.py)\n");
}

}  // namespace

int sweep_command(const SweepArguments& arguments) {
  try {
    const Sweep sweep = plan_sweep(arguments);
    const std::vector<std::optional<int>> codes = run_all(arguments, sweep);
    const SweepTable table = gather(sweep, codes);
    write_results(sweep, table);
    return exit_code_of(table, codes);
  } catch (const InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  } catch (const RunError& error) {
    fmt::print(stderr, "sweep failed: {}\n", error.what());
    return kExitRunFailed;
  }
}

}  // namespace partimix::app
