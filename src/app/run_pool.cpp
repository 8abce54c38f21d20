#include "app/run_pool.hpp"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <thread>

#include <fmt/format.h>

#include "app/child_process.hpp"
#include "app/interrupt.hpp"
#include "core/error.hpp"

namespace partimix::app {
namespace {

constexpr int kNotStarted = 127;
constexpr std::chrono::milliseconds kPollInterval{20};

class Pool {
 public:
  Pool(const std::vector<PoolTask>& tasks, const TaskEnded& on_end)
      : tasks_(tasks), on_end_(on_end), codes_(tasks.size()) {}

  std::vector<std::optional<int>> run(std::size_t jobs) {
    while (!running_.empty() || (next_ < tasks_.size() && !interrupt_requested())) {
      if (interrupt_requested())
        forward_interrupt();
      while (!interrupt_requested() && next_ < tasks_.size() && running_.size() < jobs)
        start_next();
      if (!reap_one())
        std::this_thread::sleep_for(kPollInterval);
    }
    return codes_;
  }

 private:
  void start_next() {
    const std::size_t index = next_++;
    try {
      running_[start_process(tasks_[index].argv, tasks_[index].log)] = index;
    } catch (const RunError& error) {
      fmt::print(stderr, "error: {}\n", error.what());
      finish(index, kNotStarted);
    }
  }

  bool reap_one() {
    if (running_.empty())
      return false;
    const std::optional<Ended> ended = poll_ended_process();
    if (!ended)
      return false;
    const auto found = running_.find(ended->pid);
    if (found == running_.end())
      return true;
    const std::size_t index = found->second;
    running_.erase(found);
    finish(index, ended->exit_code);
    return true;
  }

  void finish(std::size_t index, int exit_code) {
    codes_[index] = exit_code;
    on_end_(index, exit_code);
  }

  void forward_interrupt() {
    if (forwarded_)
      return;
    forwarded_ = true;
    for (const auto& [pid, index] : running_)
      ::kill(pid, SIGINT);
  }

  const std::vector<PoolTask>& tasks_;
  const TaskEnded& on_end_;
  std::vector<std::optional<int>> codes_;
  std::map<pid_t, std::size_t> running_;
  std::size_t next_ = 0;
  bool forwarded_ = false;
};

}  // namespace

std::vector<std::optional<int>> run_pool(const std::vector<PoolTask>& tasks, int jobs,
                                         const TaskEnded& on_end) {
  return Pool(tasks, on_end).run(static_cast<std::size_t>(std::max(jobs, 1)));
}

}  // namespace partimix::app
