// A sliding body stays in place while its surface moves at the given velocity, brought up by
// the start-up ramp (docs/motions.md).
#include <gtest/gtest.h>

#include "geometry/motion.hpp"

namespace partimix::geometry {
namespace {

TEST(SlidingMotion, StaysInPlaceWhileItsSurfaceMovesAtTheRampedVelocity) {
  MotionConfig config;
  config.type = "sliding";
  config.velocity = Vec3(1.0, 0.0, 0.0);
  config.ramp_time = 0.2;
  const auto motion = motion_registry().create("sliding", config);
  const Vec3 start(0.3, 1.0, 0.0);
  for (const double t : {0.0, 0.1, 0.2, 5.0}) {
    const RigidPose pose = motion->pose(t);
    EXPECT_NEAR((pose.place(start) - start).norm(), 0.0, 1e-15) << t;
  }
  EXPECT_NEAR(motion->pose(0.0).velocity_at(start).norm(), 0.0, 1e-15);
  EXPECT_NEAR(motion->pose(0.1).velocity_at(start).x(), 0.5, 1e-12);
  EXPECT_NEAR(motion->pose(5.0).velocity_at(start).x(), 1.0, 1e-15);
  EXPECT_NEAR(motion->pose(5.0).velocity_at(Vec3(9.0, -2.0, 0.0)).x(), 1.0, 1e-15);
}

}  // namespace
}  // namespace partimix::geometry
