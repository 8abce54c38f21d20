#pragma once
// What a run will cost, known before it starts (docs/case-reference.md, "limits"): its first
// time step, and from it the number of steps, series rows and frames. `run` and `check` refuse
// a case whose first step cannot be taken or whose steps pass limits.steps; `check` also takes
// the first step, so that a case that fails at once fails there and not after its set-up.
#include "app/simulation.hpp"
#include "io/case.hpp"

namespace partimix::app {

struct RunEstimate {
  double first_dt = 0.0;  // [s]
  double steps = 0.0;     // time.end / first_dt
  double series_rows = 0.0;
  double frames = 0.0;
};

// Throws InputError at the key that decides it: time.dt when a fixed step exceeds a method's
// stable step, time.end when the step is below 1e-9 time.end (no progress) or when the steps
// pass limits.steps.
RunEstimate estimate_run(const io::Case& the_case, Simulation& simulation);

// Takes the first step (changing the simulation) and throws InputError at the section of the
// first method whose particles it leaves non-finite or outside the domain, or at the first
// method's section when the step itself fails (a solve that does not converge: a RunError,
// which `check` would otherwise not catch).
void take_first_step(const io::Case& the_case, Simulation& simulation, double dt);

}  // namespace partimix::app
