#include "core/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace partimix {
namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string clock_time(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) {
    return "--:--:--";
  }
  const auto total = static_cast<long long>(std::llround(seconds));
  return fmt::format("{:02}:{:02}:{:02}", total / 3600, total / 60 % 60, total % 60);
}

}  // namespace

Progress::Progress(double end_time, std::FILE* stream, bool live, double plain_interval,
                   Clock clock)
    : end_time_(end_time),
      stream_(stream),
      live_(live),
      interval_(live ? kLiveInterval : plain_interval),
      clock_(clock ? std::move(clock) : Clock(steady_seconds)),
      start_(clock_()),
      last_print_(start_) {}

void Progress::update(double time, std::size_t steps, std::size_t particles) {
  const std::size_t new_steps = steps > steps_ ? steps - steps_ : 0;
  particle_steps_ += static_cast<double>(new_steps) * static_cast<double>(particles);
  time_ = time;
  steps_ = steps;
  pending_ = true;
  const double now = clock_();
  if (now - last_print_ >= interval_) {
    print(now);
  }
}

void Progress::finish() {
  if (finished_) {
    return;
  }
  finished_ = true;
  if (pending_) {
    print(clock_());
  }
  if (live_ && drawn_width_ > 0) {
    std::fputc('\n', stream_);
    std::fflush(stream_);
  }
}

std::string Progress::line(double now) const {
  const double elapsed = now - start_;
  const double fraction = end_time_ > 0.0 ? std::clamp(time_ / end_time_, 0.0, 1.0) : 1.0;
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
  const double rate = elapsed > 0.0 ? particle_steps_ / elapsed : 0.0;
  return fmt::format("t = {:.4g} s  {:.1f}%  ETA {}  {:.2e} particle-steps/s", time_,
                     100.0 * fraction, clock_time(eta), rate);
}

void Progress::print(double now) {
  const std::string text = line(now);
  if (live_) {
    fmt::print(stream_, "\r{:<{}}", text, drawn_width_);
    drawn_width_ = std::max(drawn_width_, text.size());
  } else {
    fmt::print(stream_, "{}\n", text);
  }
  std::fflush(stream_);
  last_print_ = now;
  pending_ = false;
}

}  // namespace partimix
