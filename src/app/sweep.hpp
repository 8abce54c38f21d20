#pragma once
// `partimix sweep` (docs/sweeps.md): run a case for every combination of the values of some
// keys, each run a child process, and gather their status and summary figures in one table.
#include <filesystem>
#include <string>
#include <vector>

namespace partimix::app {

struct SweepArguments {
  std::string case_file;
  std::vector<std::string> varied;     // --vary KEY=v1,v2,...
  std::vector<std::string> overrides;  // --set KEY=value, the same in every run
  std::filesystem::path output_dir;    // empty: out/<case name>_sweep
  int jobs = 1;                        // runs at a time
  int threads = 0;                     // OpenMP threads per run; 0: cores / jobs, at least 1
  bool overwrite = false;              // write into a folder with files partimix did not write
};

// Returns 0 when every run completed, 1 when one did not, 2 on bad input (nothing written),
// 130 after Ctrl-C (the runs started end and the table is written).
int sweep_command(const SweepArguments& arguments);

}  // namespace partimix::app
