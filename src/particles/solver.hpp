#pragma once
// The interface every method implements (DESIGN.md, "One run"): the Runner asks each solver
// for its stable time step, steps it, and hands its particles (read-only) to analyses and
// writers. The Runner never names a concrete method.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/state_archive.hpp"
#include "particles/domain.hpp"
#include "particles/frame_array.hpp"
#include "particles/grid_frame.hpp"
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
  // Arrays that a frame carries beside the store's output fields, computed from the current
  // state when a frame is written, never in a step (particles/frame_array.hpp). None by default.
  virtual std::vector<FrameArray> frame_arrays() { return {}; }
  // A method on a grid: the frame of its cells (particles/grid_frame.hpp), written in place of
  // its particles, computed from the current state; its arrays stay valid until the next step
  // or call. Null for a method whose frames are its particles (the default).
  virtual const GridFrame* grid_frame() { return nullptr; }
  // The method's full state for a checkpoint, under `prefix` ("methods/sph/"): its particles'
  // fields (particles/store_state.hpp) and whatever else its next step reads (contact
  // histories, its time and step count, the inputs of its time step). After restore() the
  // method continues bit for bit as if it had never stopped. restore() throws StateError when
  // the archive does not fit the method as built (another particle count or set of fields).
  virtual void save(StateArchive& archive, const std::string& prefix) const = 0;
  virtual void restore(const StateArchive& archive, const std::string& prefix) = 0;
};

}  // namespace partimix
