#pragma once
// The interface every method implements (DESIGN.md, "One run"): the Runner asks each solver
// for its stable time step, steps it, and hands its particles (read-only) to analyses and
// writers. The Runner never names a concrete method.
#include <map>
#include <string>
#include <string_view>

#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix {

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string_view name() const = 0;
  virtual const ParticleStore& particles() const = 0;
  virtual const Domain& domain() const = 0;
  virtual double stable_dt() const = 0;
  virtual void step(double dt) = 0;
  // Numbers the solver derived from the case (smoothing length, sound speed, ...) for run.json
  // and `partimix check`, by name with the unit in brackets.
  virtual std::map<std::string, double> derived_parameters() const = 0;
  // Fills the vector fields "body_force" and "body_couple" of the particles: the force on each
  // body (wall) particle from the material around it [N] and its couple [N m], at the current
  // state. Analyses of body loads call it before sampling; a solver without bodies leaves the
  // fields absent.
  virtual void update_body_forces() {}
};

}  // namespace partimix
