#include "geometry/planetary_motion.hpp"

#include <Eigen/Geometry>

#include "geometry/revolutions.hpp"

namespace partimix::geometry {

PlanetaryMotion::PlanetaryMotion(const Vec3& own_axis_point, const Vec3& centre, const Vec3& axis,
                                 double spin_rpm, double revolution_rpm, double ramp_time)
    : own_axis_point_(own_axis_point),
      centre_(centre),
      axis_(axis.normalized()),
      spin_(radians_per_second(spin_rpm)),
      revolution_(radians_per_second(revolution_rpm)),
      ramp_(ramp_time) {}

RigidPose PlanetaryMotion::pose(double time) const {
  const double angle_time = ramp_.equivalent_time(time);
  const double fraction = ramp_.speed_fraction(time);
  const Mat3 revolution = Eigen::AngleAxisd(revolution_ * angle_time, axis_).toRotationMatrix();
  RigidPose pose;
  pose.start_origin = own_axis_point_;
  pose.origin = centre_ + revolution * (own_axis_point_ - centre_);
  pose.rotation = Eigen::AngleAxisd(spin_ * angle_time, axis_).toRotationMatrix();
  pose.velocity = (revolution_ * fraction) * axis_.cross(pose.origin - centre_);
  pose.angular_velocity = (spin_ * fraction) * axis_;
  return pose;
}

}  // namespace partimix::geometry
