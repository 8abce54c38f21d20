#include "app/run_clock.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

namespace partimix::app {

double step_towards_end(double step, double remaining) {
  if (remaining <= step)
    return remaining;
  return remaining < 2.0 * step ? 0.5 * remaining : step;
}

RunClock::RunClock(const io::Case& the_case, Simulation& simulation)
    : case_(the_case), simulation_(simulation) {}

std::optional<double> RunClock::next_step(double remaining, std::string& why) const {
  double adaptive = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < simulation_.methods.size(); ++m) {
    const io::MethodSpec& spec = case_.methods[m];
    const double stable = spec.sub_steps * simulation_.methods[m].solver->stable_dt();
    const std::optional<double>& fixed = case_.time.fixed_dt;
    if (fixed && *fixed > stable) {
      why = fmt::format(
          "time.dt = {:.6g} s exceeds the stable step of method {} ({:.6g} s, times sub_steps "
          "{}); lower time.dt or raise time.sub_steps.{}",
          *fixed, spec.name, stable / spec.sub_steps, spec.sub_steps, spec.name);
      return std::nullopt;
    }
    adaptive = std::min(adaptive, stable);
  }
  if (case_.time.fixed_dt)
    return std::min(*case_.time.fixed_dt, remaining);
  return step_towards_end(adaptive, remaining);
}

void RunClock::advance(double time, double dt) {
  for (auto& coupling : simulation_.couplings)
    coupling->exchange(time, dt);
  for (std::size_t m = 0; m < simulation_.methods.size(); ++m) {
    for (auto& coupling : simulation_.couplings)
      coupling->before_method(m, time, dt);
    const int sub_steps = case_.methods[m].sub_steps;
    const double sub_dt = dt / sub_steps;
    for (int s = 0; s < sub_steps; ++s)
      simulation_.methods[m].solver->step(sub_dt);
  }
}

}  // namespace partimix::app
