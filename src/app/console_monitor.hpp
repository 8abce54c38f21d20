#pragma once
// The set-up phases of a run or a check on the console (core/phase_monitor.hpp): each phase is
// announced once, then shown like the run's progress line, and stops when the user presses
// Ctrl-C or sends SIGTERM (app/interrupt.hpp).
#include <cstdio>
#include <optional>
#include <string>

#include "core/phase_monitor.hpp"
#include "core/progress.hpp"

namespace partimix::app {

class ConsoleMonitor : public PhaseMonitor {
 public:
  explicit ConsoleMonitor(std::FILE* stream);
  void update(const std::string& phase, double done, double total, std::size_t steps,
              std::size_t particles) override;
  bool stop_requested() const override;
  // Ends the line of the phase under way, if any.
  void finish();

 private:
  std::FILE* stream_;
  std::string phase_;
  std::optional<Progress> progress_;
};

}  // namespace partimix::app
