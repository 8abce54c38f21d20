#include "app/optimise.hpp"

#include <omp.h>

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/child_process.hpp"
#include "app/design_variables.hpp"
#include "app/evaluation_cache.hpp"
#include "app/interrupt.hpp"
#include "app/output_folder.hpp"
#include "app/run_record.hpp"
#include "app/sweep_table.hpp"
#include "app/tools_dir.hpp"
#include "core/derivative_free_search.hpp"
#include "core/error.hpp"
#include "io/case.hpp"

namespace partimix::app {
namespace {

namespace fs = std::filesystem;

struct Search {
  std::vector<DesignVariable> variables;
  std::vector<double> start;
  std::vector<double> lower;
  std::vector<double> upper;
  fs::path dir;
};

// The fixed overrides, then the design's, so that a varied key wins.
std::vector<std::string> run_overrides(const OptimiseArguments& arguments, const Search& search,
                                       const std::vector<double>& x) {
  std::vector<std::string> overrides = arguments.overrides;
  const std::vector<std::string> design = design_overrides(search.variables, x);
  overrides.insert(overrides.end(), design.begin(), design.end());
  return overrides;
}

// Checks the arguments and the case at the start and at both ends of every key's range.
Search plan_search(const OptimiseArguments& arguments) {
  Search search;
  search.variables = parse_design_variables(arguments.varied);
  const std::vector<std::string>& names = search_algorithms();
  if (std::find(names.begin(), names.end(), arguments.algorithm) == names.end())
    throw InputError({"--algorithm", 0, 0, ""},
                     fmt::format("'{}' is not one of {}", arguments.algorithm, names));
  const io::Case base = io::load_case(arguments.case_file, arguments.overrides);
  for (const DesignVariable& variable : search.variables) {
    search.start.push_back(start_value(variable, base.resolved));
    search.lower.push_back(variable.lower);
    search.upper.push_back(variable.upper);
  }
  for (const std::vector<double>& x : {search.start, search.lower, search.upper})
    io::load_case(arguments.case_file, run_overrides(arguments, search, x));
  search.dir = arguments.output_dir.empty() ? fs::path("out") / (base.name + "_optimise")
                                            : arguments.output_dir;
  return search;
}

nlohmann::json describe(const OptimiseArguments& arguments, const Search& search) {
  nlohmann::json keys = nlohmann::json::array();
  for (const DesignVariable& variable : search.variables)
    keys.push_back({{"key", variable.key}, {"lower", variable.lower}, {"upper", variable.upper}});
  return {{"case", fs::absolute(arguments.case_file).lexically_normal().string()},
          {"overrides", arguments.overrides},
          {"keys", keys},
          {"minimise", arguments.figure},
          {"algorithm", arguments.algorithm}};
}

int threads_per_run(const OptimiseArguments& arguments) {
  return arguments.threads > 0 ? arguments.threads : std::max(1, omp_get_num_procs());
}

// Runs the case at x in DIR/<run>; the figure, or a RunError saying why there is none.
double run_design(const OptimiseArguments& arguments, const Search& search,
                  const std::vector<double>& x, const std::string& run) {
  const fs::path run_dir = search.dir / run;
  fs::create_directories(run_dir);
  record_output(search.dir, run);
  record_output(search.dir, run + "/log.txt");
  std::vector<std::string> argv{"/proc/self/exe", "run", arguments.case_file};
  for (const std::string& text : run_overrides(arguments, search, x)) {
    argv.push_back("--set");
    argv.push_back(text);
  }
  argv.insert(argv.end(), {"--out", run_dir.string(), "--overwrite", "--quiet", "--threads",
                           std::to_string(threads_per_run(arguments))});
  const int code = wait_process(start_process(argv, run_dir / "log.txt"));
  if (interrupt_requested())
    throw Interrupted("interrupted; run the same command again to resume");
  const RunRecord record = read_run_record(run_dir);
  const auto figure = record.figures.find(arguments.figure);
  if (code != kExitSuccess || record.status != "completed" || figure == record.figures.end())
    throw RunError(fmt::format("{} ({}) gave no figure {}: status {}, exit code {}; see {}", run,
                               fmt::join(design_overrides(search.variables, x), " "),
                               arguments.figure, record.status, code,
                               (run_dir / "log.txt").string()));
  return figure->second;
}

double evaluate(const OptimiseArguments& arguments, const Search& search, EvaluationCache& cache,
                const std::vector<double>& x) {
  const std::string design =
      fmt::format("{}", fmt::join(design_overrides(search.variables, x), " "));
  if (const std::optional<Evaluation> known = cache.find(x)) {
    fmt::print(stderr, "{} ({}): {} = {:.6g} (evaluated before)\n", known->run, design,
               arguments.figure, known->value);
    return known->value;
  }
  const std::string run = fmt::format("eval_{:03d}", cache.evaluations().size());
  const double value = run_design(arguments, search, x, run);
  cache.add({x, run, value});
  fmt::print(stderr, "{} ({}): {} = {:.6g}\n", run, design, arguments.figure, value);
  return value;
}

// The table of every evaluation, in order: run, keys, status and figures (optimise.csv).
void write_table(const Search& search, const EvaluationCache& cache) {
  SweepTable table;
  for (const DesignVariable& variable : search.variables)
    table.keys.push_back(variable.key);
  for (const Evaluation& evaluation : cache.evaluations()) {
    std::vector<std::string> values;
    for (double v : evaluation.x)
      values.push_back(fmt::format("{:.10g}", v));
    table.rows.push_back({evaluation.run, values, read_run_record(search.dir / evaluation.run)});
  }
  write_sweep_csv(search.dir / "optimise.csv", table);
}

void plot_search(const OptimiseArguments& arguments, const Search& search) {
  const fs::path script = tools_dir() / "plot_optimise.py";
  int code = kExitRunFailed;
  try {
    code = wait_process(start_process(
        {"/usr/bin/python3", script.string(), search.dir.string(), arguments.figure}));
  } catch (const RunError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
  }
  if (code != kExitSuccess)
    fmt::print(stderr, "warning: the search plot failed (tools/plot_optimise.py)\n");
}

void report_best(const OptimiseArguments& arguments, const Search& search,
                 const EvaluationCache& cache, const std::string& reason) {
  const auto best =
      std::min_element(cache.evaluations().begin(), cache.evaluations().end(),
                       [](const Evaluation& a, const Evaluation& b) { return a.value < b.value; });
  fmt::print(stderr, "search ended after {} evaluations: {}\n", cache.evaluations().size(), reason);
  if (best != cache.evaluations().end())
    fmt::print(stderr, "best: {} with {}: {} = {:.6g}\n", best->run,
               fmt::join(design_overrides(search.variables, best->x), " "), arguments.figure,
               best->value);
  fmt::print(stderr, "table: {}\n", (search.dir / "optimise.csv").string());
}

SearchSettings settings_of(const OptimiseArguments& arguments) {
  SearchSettings settings;
  settings.algorithm = arguments.algorithm;
  settings.max_evaluations = arguments.evaluations;
  settings.stop_value = arguments.target;
  return settings;
}

int search_and_report(const OptimiseArguments& arguments, const Search& search,
                      EvaluationCache& cache) {
  std::string reason;
  int code = kExitSuccess;
  try {
    reason =
        minimise(
            [&](const std::vector<double>& x) { return evaluate(arguments, search, cache, x); },
            search.lower, search.upper, search.start, settings_of(arguments))
            .reason;
  } catch (const RunError& error) {
    reason = fmt::format("a run failed: {}", error.what());
    code = kExitRunFailed;
  } catch (const Interrupted& error) {
    reason = error.what();
    code = kExitInterrupted;
  }
  write_table(search, cache);
  if (!cache.evaluations().empty())
    plot_search(arguments, search);
  report_best(arguments, search, cache, reason);
  return code;
}

}  // namespace

int optimise_command(const OptimiseArguments& arguments) {
  try {
    const Search search = plan_search(arguments);
    const fs::path file = search.dir / "evaluations.json";
    if (!fs::exists(file))
      prepare_output_folder(search.dir, false);
    EvaluationCache cache(file, describe(arguments, search));
    for (const char* name : {"evaluations.json", "optimise.csv", "search.png"})
      record_output(search.dir, name);
    fmt::print(stderr,
               "partimix optimise: {} of {} by {}, at most {} evaluations ({} made) -> {}\n",
               arguments.figure, arguments.case_file, arguments.algorithm, arguments.evaluations,
               cache.evaluations().size(), search.dir.string());
    install_interrupt_handler();
    return search_and_report(arguments, search, cache);
  } catch (const InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  } catch (const RunError& error) {
    fmt::print(stderr, "optimise failed: {}\n", error.what());
    return kExitRunFailed;
  }
}

}  // namespace partimix::app
