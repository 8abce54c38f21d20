#include "app/child_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"

extern char** environ;

namespace partimix::app {
namespace {

int exit_code_of(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// The file actions that send stdout and stderr to `log`, if any.
class Redirection {
 public:
  explicit Redirection(const std::filesystem::path& log) {
    posix_spawn_file_actions_init(&actions_);
    if (log.empty())
      return;
    posix_spawn_file_actions_addopen(&actions_, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions_, STDOUT_FILENO, STDERR_FILENO);
  }
  ~Redirection() { posix_spawn_file_actions_destroy(&actions_); }
  Redirection(const Redirection&) = delete;
  Redirection& operator=(const Redirection&) = delete;

  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

}  // namespace

pid_t start_process(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  std::vector<std::string> words = argv;
  std::vector<char*> pointers;
  for (std::string& word : words)
    pointers.push_back(word.data());
  pointers.push_back(nullptr);
  const Redirection redirection(log);
  pid_t pid = -1;
  const int error =
      posix_spawn(&pid, pointers[0], redirection.get(), nullptr, pointers.data(), environ);
  if (error != 0)
    throw RunError("cannot start '" + argv.front() + "': " + std::strerror(error));
  return pid;
}

int wait_process(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR)
      throw RunError("waiting for a child process failed: " + std::string(std::strerror(errno)));
  }
  return exit_code_of(status);
}

std::optional<Ended> poll_ended_process() {
  int status = 0;
  const pid_t pid = ::waitpid(-1, &status, WNOHANG);
  if (pid <= 0)
    return std::nullopt;
  return Ended{pid, exit_code_of(status)};
}

}  // namespace partimix::app
