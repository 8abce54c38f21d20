// Translation (docs/motions.md): a body moving at v = (0.3, -0.2, 0.1) m/s from t = 0.5 s to
// t = 2 s is at rest at its start before, at X + v (t - 0.5) between, and at X + 1.5 v after,
// with velocity v only for 0.5 <= t < 2, at every point, and no rotation. Positions are exact
// but for the round-off of v (t - start) (1e-15 m); velocities are exact.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "geometry/motion.hpp"
#include "geometry/translation_motion.hpp"

namespace partimix::geometry {
namespace {

constexpr double kRoundOff = 1e-15;
const Vec3 kVelocity(0.3, -0.2, 0.1);
const Vec3 kStart(1.0, 2.0, -0.5);  // X, a point of the body at t = 0

MotionConfig gate(double start, double stop) {
  MotionConfig config;
  config.type = "translation";
  config.velocity = kVelocity;
  config.start = start;
  config.stop = stop;
  return config;
}

void expect_pose(const Motion& motion, double t, const Vec3& displacement, const Vec3& velocity) {
  const RigidPose pose = motion.pose(t);
  const Vec3 x = pose.place(kStart);
  EXPECT_LT((x - (kStart + displacement)).norm(), kRoundOff) << "at t = " << t;
  EXPECT_EQ(pose.velocity_at(x), velocity) << "at t = " << t;
  EXPECT_EQ(pose.velocity_at(Vec3(-3.0, 4.0, 7.0)), velocity) << "at t = " << t;
  EXPECT_EQ(pose.rotation, Mat3::Identity());
  EXPECT_EQ(pose.angular_velocity, Vec3::Zero());
}

TEST(TranslationMotion, RestMovesAndRestsAgain) {
  const auto motion = motion_registry().create("translation", gate(0.5, 2.0));
  ASSERT_NE(motion, nullptr);
  EXPECT_TRUE(motion->moves());
  expect_pose(*motion, 0.0, Vec3::Zero(), Vec3::Zero());
  expect_pose(*motion, 0.3, Vec3::Zero(), Vec3::Zero());
  expect_pose(*motion, 0.5, Vec3::Zero(), kVelocity);
  expect_pose(*motion, 1.25, 0.75 * kVelocity, kVelocity);
  expect_pose(*motion, 2.0, 1.5 * kVelocity, Vec3::Zero());
  expect_pose(*motion, 7.0, 1.5 * kVelocity, Vec3::Zero());
}

TEST(TranslationMotion, PositionIsContinuousAtStartAndStop) {
  const TranslationMotion motion(kVelocity, 0.5, 2.0);
  const double dt = 1e-9;
  for (const double t : {0.5, 2.0}) {
    const Vec3 before = motion.pose(t - dt).place(kStart);
    const Vec3 after = motion.pose(t + dt).place(kStart);
    EXPECT_LT((after - before).norm(), dt * kVelocity.norm() + kRoundOff) << "at t = " << t;
  }
}

TEST(TranslationMotion, WithoutStopItNeverRests) {
  // A gate lifted at t = 0: the defaults start 0 and stop infinity.
  MotionConfig config;
  config.type = "translation";
  config.velocity = Vec3(0.0, 0.25, 0.0);
  const auto motion = motion_registry().create("translation", config);
  for (const double t : {0.0, 0.2, 100.0}) {
    const RigidPose pose = motion->pose(t);
    EXPECT_LT((pose.place(kStart) - (kStart + Vec3(0.0, 0.25 * t, 0.0))).norm(),
              kRoundOff * (1.0 + t))
        << "at t = " << t;
    EXPECT_EQ(pose.velocity, Vec3(0.0, 0.25, 0.0)) << "at t = " << t;
  }
}

TEST(TranslationMotion, StopBeforeStartIsRefused) {
  EXPECT_THROW(TranslationMotion(kVelocity, 2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(TranslationMotion(kVelocity, std::numeric_limits<double>::quiet_NaN(), 1.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace partimix::geometry
