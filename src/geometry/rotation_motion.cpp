#include "geometry/rotation_motion.hpp"

#include <Eigen/Geometry>

#include "geometry/revolutions.hpp"

namespace partimix::geometry {

RotationMotion::RotationMotion(const Vec3& axis_point, const Vec3& axis, double rpm,
                               double ramp_time, const std::vector<SpeedChange>& schedule)
    : axis_point_(axis_point), axis_(axis.normalized()), ramp_(ramp_time) {
  steps_.push_back({0.0, radians_per_second(rpm)});
  double previous = rpm;
  for (const SpeedChange& change : schedule) {
    steps_.push_back({change.time, radians_per_second(change.rpm - previous)});
    previous = change.rpm;
  }
}

RigidPose RotationMotion::pose(double time) const {
  double angle = 0.0;
  double omega = 0.0;
  for (const Step& step : steps_) {
    if (time < step.time)
      break;
    angle += step.omega * ramp_.equivalent_time(time - step.time);
    omega += step.omega * ramp_.speed_fraction(time - step.time);
  }
  RigidPose pose;
  pose.start_origin = axis_point_;
  pose.origin = axis_point_;
  pose.rotation = Eigen::AngleAxisd(angle, axis_).toRotationMatrix();
  pose.angular_velocity = omega * axis_;
  return pose;
}

}  // namespace partimix::geometry
