// Prescribed motions against closed-form trajectories (docs/motions.md): rotation about an
// axis, the planetary path (a hypotrochoid: x = e (cos theta_G, sin theta_G) + d (cos theta_R,
// sin theta_R) for a point at distance d from the own axis), the start-up ramp, and velocities
// against central differences of the positions. Tolerances: positions 1e-12 m (round-off of a
// few rotations), velocities 1e-6 relative (the O(dt^2) error of the central difference with
// dt = 1e-5 s).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/motion.hpp"

namespace partimix::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

std::unique_ptr<Motion> make(const MotionConfig& config) {
  return motion_registry().create(config.type, config);
}

// Central difference of the position of the body point that started at `start`.
Vec3 finite_difference_velocity(const Motion& motion, const Vec3& start, double t) {
  const double dt = 1.0e-5;
  return (motion.pose(t + dt).place(start) - motion.pose(t - dt).place(start)) / (2.0 * dt);
}

void expect_velocity_matches_positions(const Motion& motion, const Vec3& start, double t) {
  const RigidPose pose = motion.pose(t);
  const Vec3 velocity = pose.velocity_at(pose.place(start));
  const Vec3 difference = finite_difference_velocity(motion, start, t);
  EXPECT_LT((velocity - difference).norm(), 1e-6 * std::max(1.0, difference.norm()))
      << "at t = " << t;
}

TEST(Motion, FixedBodyStaysPut) {
  const auto motion = make(MotionConfig{});
  const RigidPose pose = motion->pose(3.0);
  EXPECT_EQ(pose.place(Vec3(1.0, 2.0, 3.0)), Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(pose.velocity_at(Vec3(1.0, 2.0, 3.0)), Vec3::Zero());
}

TEST(Motion, RotationTurnsCounterClockwiseAboutItsAxis) {
  MotionConfig config;
  config.type = "rotation";
  config.axis_point = Vec3(1.0, 1.0, 0.0);
  config.rpm = 60.0;  // one turn per second
  const auto motion = make(config);
  const Vec3 start(2.0, 1.0, 0.5);
  for (double t : {0.25, 0.5, 1.3}) {
    const Vec3 expected(1.0 + std::cos(2.0 * kPi * t), 1.0 + std::sin(2.0 * kPi * t), 0.5);
    EXPECT_LT((motion->pose(t).place(start) - expected).norm(), 1e-12) << "at t = " << t;
    expect_velocity_matches_positions(*motion, start, t);
  }
}

TEST(Motion, RotationAboutATiltedAxisKeepsTheAxisPointsFixed) {
  MotionConfig config;
  config.type = "rotation";
  config.axis = Vec3(1.0, 0.0, 1.0);  // normalised by the motion
  config.rpm = 17.0;
  const auto motion = make(config);
  const Vec3 on_axis(2.0, 0.0, 2.0);
  EXPECT_LT((motion->pose(0.7).place(on_axis) - on_axis).norm(), 1e-12);
  expect_velocity_matches_positions(*motion, Vec3(0.3, -0.2, 0.1), 0.7);
}

// The seed's planetary impeller (section 3, after Bohl 2007): e'' = 0.17 D_w, D_w = 0.1386 m,
// N_G = -25 rpm (clockwise revolution), N_R = 60 rpm.
TEST(Motion, PlanetaryPathIsTheHypotrochoid) {
  const double e = 0.17 * 0.1386;
  const double d = 0.0299;  // half the blade length d_a
  MotionConfig config;
  config.type = "planetary";
  config.centre = Vec3::Zero();
  config.axis_point = Vec3(e, 0.0, 0.0);
  config.revolution_rpm = -25.0;
  config.rpm = 60.0;
  const auto motion = make(config);
  const Vec3 start(e + d, 0.0, 0.1);
  for (double t : {0.1, 0.77, 2.4, 3.9}) {
    const double theta_g = -25.0 * 2.0 * kPi / 60.0 * t;
    const double theta_r = 60.0 * 2.0 * kPi / 60.0 * t;
    const Vec3 expected(e * std::cos(theta_g) + d * std::cos(theta_r),
                        e * std::sin(theta_g) + d * std::sin(theta_r), 0.1);
    EXPECT_LT((motion->pose(t).place(start) - expected).norm(), 1e-12) << "at t = " << t;
    expect_velocity_matches_positions(*motion, start, t);
  }
}

TEST(Motion, PlanetaryOwnAxisReturnsAfterOneRevolution) {
  MotionConfig config;
  config.type = "planetary";
  config.axis_point = Vec3(0.03, 0.0, 0.0);
  config.revolution_rpm = -25.0;
  config.rpm = 60.0;
  const auto motion = make(config);
  const RigidPose pose = motion->pose(60.0 / 25.0);
  EXPECT_LT((pose.origin - config.axis_point).norm(), 1e-12);
  EXPECT_NEAR(pose.angular_velocity.z(), 2.0 * kPi, 1e-12);
  EXPECT_NEAR(pose.velocity.norm(), 25.0 * 2.0 * kPi / 60.0 * 0.03, 1e-12);
}

TEST(Motion, StartUpRampStartsAtRestAndReachesFullSpeedSmoothly) {
  MotionConfig config;
  config.type = "rotation";
  config.rpm = 60.0;
  config.ramp_time = 0.5;
  const auto motion = make(config);
  const double omega = 2.0 * kPi;
  EXPECT_EQ(motion->pose(0.0).angular_velocity.z(), 0.0);
  EXPECT_NEAR(motion->pose(0.25).angular_velocity.z(), 0.5 * omega, 1e-12);
  EXPECT_NEAR(motion->pose(0.5).angular_velocity.z(), omega, 1e-12);
  EXPECT_NEAR(motion->pose(0.9).angular_velocity.z(), omega, 1e-12);
  const Vec3 start(1.0, 0.0, 0.0);
  for (double t : {0.1, 0.25, 0.5, 0.9})
    expect_velocity_matches_positions(*motion, start, t);
  // After the ramp the body lags the unramped one by half the ramp time: angle omega (t - T/2).
  const Vec3 expected(std::cos(omega * 0.65), std::sin(omega * 0.65), 0.0);
  EXPECT_LT((motion->pose(0.9).place(start) - expected).norm(), 1e-12);
}

// A truck drum's schedule: 14 rpm from rest over 2 s, back to -8 rpm at 60 s. The speed is
// continuous and the angle is its integral: against the trapezoidal sum of the speeds at 1e-4 s
// (error below 1e-9 rad; tolerance 1e-6 rad for the round-off of 7e5 terms), and after the last
// ramp against the closed form: each step Δω_k adds Δω_k (t - t_k - T/2).
TEST(Motion, ScheduledSpeedChangesRampAndTheAngleIsTheSpeedsIntegral) {
  MotionConfig config;
  config.type = "rotation";
  config.rpm = 14.0;
  config.ramp_time = 2.0;
  config.schedule = {{60.0, -8.0}};
  const auto motion = make(config);
  const double w1 = 14.0 * 2.0 * kPi / 60.0;
  const double w2 = -8.0 * 2.0 * kPi / 60.0;
  EXPECT_NEAR(motion->pose(30.0).angular_velocity.z(), w1, 1e-12);
  EXPECT_NEAR(motion->pose(61.0).angular_velocity.z(), 0.5 * (w1 + w2), 1e-12);
  EXPECT_NEAR(motion->pose(70.0).angular_velocity.z(), w2, 1e-12);
  double angle = 0.0;
  const double h = 1e-4;
  for (double t = 0.0; t < 70.0 - 0.5 * h; t += h)
    angle +=
        0.5 * h * (motion->pose(t).angular_velocity.z() + motion->pose(t + h).angular_velocity.z());
  const double closed_form = w1 * (70.0 - 1.0) + (w2 - w1) * (70.0 - 60.0 - 1.0);
  EXPECT_NEAR(angle, closed_form, 1e-6);
  const Vec3 start(1.0, 0.0, 0.0);
  const Vec3 expected(std::cos(closed_form), std::sin(closed_form), 0.0);
  EXPECT_LT((motion->pose(70.0).place(start) - expected).norm(), 1e-12);
  for (double t : {1.0, 59.5, 60.5, 61.9, 65.0})
    expect_velocity_matches_positions(*motion, start, t);
}

}  // namespace
}  // namespace partimix::geometry
