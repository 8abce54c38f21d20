#pragma once
// The walls of a grid fluid as bodies moving relative to its frame (docs/cfd.md, "Moving walls
// and the rotating frame"): the velocity of a wall's surface at a frame point, which no-slip
// gives the fluid beside it, and the check that each wall's surface stays in place on the grid
// (a fixed or sliding wall in the lab, a surface of revolution turning about its own axis, the
// frame's own body), since its cells are blocked once.
#include <memory>
#include <span>
#include <vector>

#include "cfd/fluid_frame.hpp"
#include "geometry/motion.hpp"
#include "geometry/surface.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

// When the check looks: `start` (the end of every start-up ramp) plus these fractions of
// `period` (a turn of the fastest motion), chosen so that no symmetry of a shape maps it onto
// itself at all of them.
struct InPlaceSamples {
  double start = 0.0;   // [s]
  double period = 1.0;  // [s]
};

class WallMotions {
 public:
  WallMotions(std::vector<std::shared_ptr<const geometry::Motion>> motions, FluidFrame frame);

  // Whether any wall moves relative to the frame (a wall velocity is then set each step); the
  // frame's own body does not.
  bool any_moving() const { return any_moving_; }
  // Takes the frame's and the walls' poses at `time`, for velocity().
  void set_time(double time);
  // Wall w's velocity at frame point x relative to the frame, in frame directions, at the time
  // last set: Rᵀ (v_w(X) - v_frame(X)) with X = place(x).
  Vec3 velocity(std::size_t wall, const Vec3& x) const;
  // The first wall whose surface, seen from the frame, is not where it was at t = 0 at one of
  // the sampled times (by more than 1e-6 h at the centre of a cell within 2 h of it); -1 if none.
  int first_not_in_place(const grid::StaggeredGrid& grid,
                         std::span<const std::shared_ptr<const geometry::Surface>> surfaces,
                         const InPlaceSamples& samples) const;

 private:
  bool in_place(const grid::StaggeredGrid& grid, std::size_t wall, const geometry::Surface& surface,
                const InPlaceSamples& samples) const;

  std::vector<std::shared_ptr<const geometry::Motion>> motions_;
  FluidFrame frame_;
  bool any_moving_ = false;
  geometry::RigidPose frame_pose_;               // at the time last set
  std::vector<geometry::RigidPose> wall_poses_;  // likewise, by wall
};

}  // namespace partimix::cfd
