#pragma once
// Rotation at N rpm about a fixed axis (docs/motions.md): central impellers on the vessel axis,
// eccentric ones on an axis offset from it, rotating drums and Taylor-Couette cylinders.
#include "geometry/motion.hpp"
#include "geometry/start_up_ramp.hpp"

namespace partimix::geometry {

class RotationMotion final : public Motion {
 public:
  RotationMotion(const Vec3& axis_point, const Vec3& axis, double rpm, double ramp_time);
  RigidPose pose(double time) const override;

 private:
  Vec3 axis_point_;
  Vec3 axis_;
  double omega_;  // [rad/s]
  StartUpRamp ramp_;
};

}  // namespace partimix::geometry
