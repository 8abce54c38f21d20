#pragma once
// A surface that slides along itself (docs/motions.md): the lid of a driven cavity, a belt. The
// body stays where it is and its surface moves at `velocity` (times the start-up ramp), which
// is what an endless lid or belt does; the velocity must be tangent to the surface for that to
// hold, which the case's author sees to (a lid along x, a belt along its length).
#include "geometry/motion.hpp"
#include "geometry/start_up_ramp.hpp"

namespace partimix::geometry {

class SlidingMotion final : public Motion {
 public:
  SlidingMotion(const Vec3& velocity, double ramp_time) : velocity_(velocity), ramp_(ramp_time) {}

  // o(t) = o0, R = I, v_o = v s(t).
  RigidPose pose(double time) const override {
    RigidPose pose;
    pose.velocity = ramp_.speed_fraction(time) * velocity_;
    return pose;
  }

 private:
  Vec3 velocity_;
  StartUpRamp ramp_;
};

}  // namespace partimix::geometry
