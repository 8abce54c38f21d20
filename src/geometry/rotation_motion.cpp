#include "geometry/rotation_motion.hpp"

#include <Eigen/Geometry>

#include "geometry/revolutions.hpp"

namespace partimix::geometry {

RotationMotion::RotationMotion(const Vec3& axis_point, const Vec3& axis, double rpm,
                               double ramp_time)
    : axis_point_(axis_point),
      axis_(axis.normalized()),
      omega_(radians_per_second(rpm)),
      ramp_(ramp_time) {}

RigidPose RotationMotion::pose(double time) const {
  RigidPose pose;
  pose.start_origin = axis_point_;
  pose.origin = axis_point_;
  pose.rotation = Eigen::AngleAxisd(omega_ * ramp_.equivalent_time(time), axis_).toRotationMatrix();
  pose.angular_velocity = (omega_ * ramp_.speed_fraction(time)) * axis_;
  return pose;
}

}  // namespace partimix::geometry
