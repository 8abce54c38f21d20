#include "app/preflight.hpp"

#include <string>

#include <fmt/format.h>

#include "app/run_clock.hpp"
#include "core/error.hpp"
#include "particles/health.hpp"

namespace partimix::app {

RunEstimate estimate_run(const io::Case& the_case, Simulation& simulation) {
  const io::TimeControl& time = the_case.time;
  std::string why;
  const std::optional<double> dt = RunClock(the_case, simulation).next_step(time.end, why);
  if (!dt)
    throw InputError(the_case.locate("time.dt"), why);
  if (!(*dt > 1e-9 * time.end)) {
    throw InputError(the_case.locate(time.fixed_dt ? "time.dt" : "time.end"),
                     fmt::format("the first time step is {:.3g} s, below 1e-9 of time.end = "
                                 "{:.6g} s: the run could not make progress",
                                 *dt, time.end));
  }
  RunEstimate estimate{*dt, time.end / *dt, time.end / time.sample_interval,
                       the_case.output.frames ? time.end / time.output_interval : 0.0};
  if (estimate.steps > the_case.limits.steps) {
    throw InputError(the_case.locate("time.end"),
                     fmt::format("at the first time step, {:.3g} s, the run takes about {:.3g} "
                                 "steps, more than limits.steps = {:.3g}; shorten time.end or "
                                 "raise limits.steps",
                                 *dt, estimate.steps, the_case.limits.steps));
  }
  return estimate;
}

void take_first_step(const io::Case& the_case, Simulation& simulation, double dt) {
  const std::string& first = the_case.methods.front().name;
  try {
    RunClock(the_case, simulation).advance(0.0, dt);
  } catch (const RunError& error) {
    throw InputError(the_case.locate(first),
                     fmt::format("the first step (dt = {:.3g} s) fails: {}", dt, error.what()));
  }
  for (std::size_t m = 0; m < simulation.methods.size(); ++m) {
    const io::MethodInstance& method = simulation.methods[m];
    if (const auto bad = find_bad_particle(*method.store, method.solver->domain())) {
      const std::string& name = the_case.methods[m].name;
      throw InputError(
          the_case.locate(name),
          fmt::format("the first step of method {} (dt = {:.3g} s) fails: {}", name, dt, *bad));
    }
  }
}

}  // namespace partimix::app
