#pragma once
// A simulation built from a case (DESIGN.md, "One run"): the particle store filled from the
// case geometry, and the solver chosen by the case's `solver` key.
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "geometry/moving_bodies.hpp"
#include "io/case.hpp"
#include "particles/particle_store.hpp"
#include "particles/solver.hpp"

namespace partimix::app {

struct Simulation {
  std::unique_ptr<ParticleStore> store;
  std::unique_ptr<geometry::MovingBodies> bodies;  // one per wall of the case
  std::unique_ptr<Solver> solver;
  std::vector<std::string> warnings;  // about the case as built, e.g. a see-through solid wall
};

// Throws InputError (naming the case key) when the case cannot be built, e.g. particles that
// fall outside the domain or a periodic axis too short for the kernel.
Simulation build_simulation(const io::Case& the_case);

// An InputError of the case file at `key` (no line: the case is loaded; the problem shows when it
// is built).
InputError case_error(const io::Case& the_case, const std::string& key, const std::string& what);

}  // namespace partimix::app
