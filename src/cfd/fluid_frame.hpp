#pragma once
// The frame the grid fluid is solved in (docs/cfd.md, "Moving walls and the rotating frame"):
// the lab, or the body of a wall turning about a fixed axis (`cfd.rotating_frame`), whose walls
// then stay on the grid. A frame point x is at place(x) in the lab at time t; the frame turns at
// Ω(t) about the axis through a, and the fluid in it feels, per unit mass, the gravity Rᵀ(t) g
// and the fictitious accelerations -2 Ω × u - Ω × (Ω × (x - a)) - (dΩ/dt) × (x - a).
#include <memory>

#include "core/vec.hpp"
#include "geometry/motion.hpp"

namespace partimix::cfd {

// What the momentum equation needs of the frame at one instant, in frame coordinates.
struct FrameForces {
  Vec3 gravity = Vec3::Zero();     // Rᵀ g [m/s²]
  Vec3 omega = Vec3::Zero();       // Ω [rad/s]
  Vec3 omega_rate = Vec3::Zero();  // dΩ/dt [rad/s²]
  Vec3 axis_point = Vec3::Zero();  // a [m]
  bool rotating = false;
};

class FluidFrame {
 public:
  // The lab frame.
  FluidFrame() = default;
  // The frame of a body in `motion`, a rotation about a fixed axis.
  explicit FluidFrame(std::shared_ptr<const geometry::Motion> motion);

  bool rotating() const { return motion_ != nullptr; }
  // Whether the frame turns with `motion` itself (the frame's own body).
  bool follows(const geometry::Motion& motion) const { return motion_.get() == &motion; }
  // The frame's pose at time t (the identity for the lab).
  geometry::RigidPose pose(double time) const;
  FrameForces forces(double time, const Vec3& gravity) const;

 private:
  std::shared_ptr<const geometry::Motion> motion_;
};

// The lab velocity of fluid at frame point x moving at u relative to the frame, in lab
// directions: R u plus the frame's own velocity at the place of x.
Vec3 lab_velocity(const geometry::RigidPose& pose, const Vec3& x, const Vec3& u);

}  // namespace partimix::cfd
