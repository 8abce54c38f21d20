#include "cfd/fluid_frame.hpp"

#include <algorithm>
#include <utility>

namespace partimix::cfd {
namespace {

// The step of the central difference that gives dΩ/dt from the motion's Ω(t) [s].
constexpr double kRateStep = 1e-4;

}  // namespace

FluidFrame::FluidFrame(std::shared_ptr<const geometry::Motion> motion)
    : motion_(std::move(motion)) {}

geometry::RigidPose FluidFrame::pose(double time) const {
  return motion_ ? motion_->pose(time) : geometry::RigidPose{};
}

FrameForces FluidFrame::forces(double time, const Vec3& gravity) const {
  FrameForces forces;
  forces.gravity = gravity;
  if (!motion_)
    return forces;
  const geometry::RigidPose now = motion_->pose(time);
  const Mat3 back = now.rotation.transpose();
  forces.rotating = true;
  forces.gravity = back * gravity;
  forces.omega = back * now.angular_velocity;
  forces.axis_point = now.start_origin;
  const double before = std::max(0.0, time - kRateStep);
  const double after = time + kRateStep;
  forces.omega_rate =
      back * (motion_->pose(after).angular_velocity - motion_->pose(before).angular_velocity) /
      (after - before);
  return forces;
}

Vec3 lab_velocity(const geometry::RigidPose& pose, const Vec3& x, const Vec3& u) {
  return pose.rotation * u + pose.velocity_at(pose.place(x));
}

}  // namespace partimix::cfd
