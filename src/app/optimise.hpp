#pragma once
// `partimix optimise` (docs/design-loop.md): search some case keys within bounds for the design
// that minimises a summary figure, each evaluation a run of the case in a child process, with
// NLopt's derivative-free methods; resumable from the evaluations already made.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace partimix::app {

struct OptimiseArguments {
  std::string case_file;
  std::vector<std::string> varied;     // --vary KEY=lo:hi
  std::vector<std::string> overrides;  // --set KEY=value, the same in every run
  std::string figure;                  // --minimise FIGURE (a run.json figure)
  std::optional<double> target;        // --target: stop once the figure is at or below it
  std::string algorithm = "bobyqa";
  int evaluations = 20;
  std::filesystem::path output_dir;  // empty: out/<case name>_optimise
  int threads = 0;                   // per run; 0: all cores
};

// Returns 0 when the search ended (the best design is named), 1 when a run failed or gave no
// such figure (the table so far is written; run again to resume), 2 on bad input (nothing
// written), 130 after Ctrl-C.
int optimise_command(const OptimiseArguments& arguments);

}  // namespace partimix::app
