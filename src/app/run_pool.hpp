#pragma once
// Runs a list of programs as child processes, a few at a time, so that one that fails or
// crashes leaves the others running (the runs of `partimix sweep`).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace partimix::app {

struct PoolTask {
  std::vector<std::string> argv;  // argv[0]: the program's path
  std::filesystem::path log;      // its stdout and stderr
};

// Called as each task ends, with its index and exit code.
using TaskEnded = std::function<void(std::size_t index, int exit_code)>;

// Runs the tasks in order, at most `jobs` at a time, and waits for all that were started.
// After Ctrl-C (app/interrupt.hpp) no task is started and the running ones get SIGINT. Returns
// each task's exit code (127 for one that could not be started), nullopt for one never started.
std::vector<std::optional<int>> run_pool(const std::vector<PoolTask>& tasks, int jobs,
                                         const TaskEnded& on_end);

}  // namespace partimix::app
