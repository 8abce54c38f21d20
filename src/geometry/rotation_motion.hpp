#pragma once
// Rotation at N rpm about a fixed axis (docs/motions.md): central impellers on the vessel axis,
// eccentric ones on an axis offset from it, rotating drums and Taylor-Couette cylinders. A
// schedule of later speeds (a truck drum charging, then turning back to discharge) changes the
// speed at each of its times through the same smooth ramp as the start-up: the speed is the sum
// of the steps Δω_k s(t - t_k), the angle that of Δω_k S(t - t_k) (docs/motions.md, "Speed
// schedule").
#include <vector>

#include "geometry/motion.hpp"
#include "geometry/start_up_ramp.hpp"

namespace partimix::geometry {

class RotationMotion final : public Motion {
 public:
  RotationMotion(const Vec3& axis_point, const Vec3& axis, double rpm, double ramp_time,
                 const std::vector<SpeedChange>& schedule = {});
  RigidPose pose(double time) const override;

 private:
  struct Step {
    double time;   // [s]
    double omega;  // the change of the angular speed [rad/s]
  };

  Vec3 axis_point_;
  Vec3 axis_;
  std::vector<Step> steps_;  // the start-up from rest, then the schedule's changes
  StartUpRamp ramp_;
};

}  // namespace partimix::geometry
