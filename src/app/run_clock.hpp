#pragma once
// The run's one clock for all its methods (DESIGN.md, "One run"; docs/architecture-notes.md,
// "Several methods in one run"). Each step of the clock lasts
//   dt = time.dt                              when the case fixes it, else
//   dt = min over the methods m of k_m dt_m   (dt_m the method's stable step),
// and method m takes k_m = time.sub_steps.m steps of dt / k_m in it, after the couplings have
// exchanged what the methods owe each other for the step, and again what they owe method m
// (coupling/coupling.hpp). With one method and k = 1 this is
// the single method's own adaptive step, bit for bit.
#include <optional>
#include <string>

#include "app/simulation.hpp"
#include "io/case.hpp"

namespace partimix::app {

// The step towards the end of the run: `step` while more than two of them remain, the rest in
// one step when it is shorter than `step`, and in between half of what remains, so that the last
// step is never shorter than half the one before. The incompressible scheme's pressure, and so
// the loads on its bodies, jump when a step is much shorter than the one before
// (docs/sph.md, "Incompressible SPH").
double step_towards_end(double step, double remaining);

class RunClock {
 public:
  RunClock(const io::Case& the_case, Simulation& simulation);

  // The next step's length, at most `remaining`. A fixed step that exceeds a method's stable
  // step (k_m dt_m) gives nullopt and the reason in `why`.
  std::optional<double> next_step(double remaining, std::string& why) const;

  // Exchanges through the couplings and steps every method over [time, time + dt].
  void advance(double time, double dt);

 private:
  const io::Case& case_;
  Simulation& simulation_;
};

}  // namespace partimix::app
