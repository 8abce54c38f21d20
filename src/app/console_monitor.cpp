#include "app/console_monitor.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include "app/interrupt.hpp"

namespace partimix::app {

ConsoleMonitor::ConsoleMonitor(std::FILE* stream) : stream_(stream) {}

void ConsoleMonitor::update(const std::string& phase, double done, double total, std::size_t steps,
                            std::size_t particles) {
  if (phase != phase_) {
    finish();
    phase_ = phase;
    fmt::print(stream_, "{} (up to t = {:.6g} s)\n", phase, total);
    progress_.emplace(total, stream_, isatty(fileno(stream_)) != 0);
  }
  progress_->update(done, steps, particles);
}

bool ConsoleMonitor::stop_requested() const {
  return interrupt_requested();
}

void ConsoleMonitor::finish() {
  if (progress_)
    progress_->finish();
  progress_.reset();
  phase_.clear();
}

}  // namespace partimix::app
