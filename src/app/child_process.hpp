#pragma once
// Programs started as child processes of partimix (the runs of a sweep, the plot scripts),
// without a shell, so that no argument needs quoting.
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace partimix::app {

// Starts the program argv[0] (a path) with arguments argv. Its stdout and stderr go to `log`
// (created or truncated) or, when `log` is empty, to those of partimix. Throws RunError naming
// the program when it cannot be started.
pid_t start_process(const std::vector<std::string>& argv, const std::filesystem::path& log = {});

// The exit code of the child `pid` once it has ended, or 128 + the signal number that ended it.
int wait_process(pid_t pid);

// Like wait_process for whichever child has ended, without waiting: nullopt while none has.
struct Ended {
  pid_t pid;
  int exit_code;
};
std::optional<Ended> poll_ended_process();

}  // namespace partimix::app
