// walls[].motion: each wall is a body with a prescribed motion (docs/case-reference.md,
// "walls"); the keys load with their defaults, and bad ones are InputErrors naming the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_files.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

// kMinimal2D with one box wall whose motion map holds `motion_lines` (already indented).
std::string with_wall_motion(const std::string& motion_lines) {
  return kMinimal2D + R"(walls:
  - shape: box
    min: [0, 0]
    max: [1.6, 1.0]
    motion:
)" + motion_lines;
}

TEST(CaseMotion, WallsAreFixedByDefault) {
  const io::Case loaded = load_text(kMinimal2D + R"(walls:
  - shape: box
    min: [0, 0]
    max: [1.6, 1.0]
)");
  EXPECT_EQ(loaded.walls.at(0).motion.type, "fixed");
  EXPECT_EQ(loaded.resolved["walls"][0]["motion"]["type"], "fixed");
}

TEST(CaseMotion, RotationLoadsWithTheZAxisIn2D) {
  const io::Case loaded = load_text(with_wall_motion(R"(      type: rotation
      axis_point: [0.8, 0.5]
      rpm: 30
      ramp_time: 0.2
)"));
  const geometry::MotionConfig& motion = loaded.walls.at(0).motion;
  EXPECT_EQ(motion.type, "rotation");
  EXPECT_EQ(motion.axis, Vec3::UnitZ());
  EXPECT_EQ(motion.axis_point, Vec3(0.8, 0.5, 0.0));
  EXPECT_DOUBLE_EQ(motion.rpm, 30.0);
  EXPECT_DOUBLE_EQ(motion.ramp_time, 0.2);
}

TEST(CaseMotion, PlanetaryLoads) {
  const io::Case loaded = load_text(with_wall_motion(R"(      type: planetary
      axis_point: [0.9, 0.5]
      centre: [0.8, 0.5]
      rpm: 60
      revolution_rpm: -25
)"));
  const geometry::MotionConfig& motion = loaded.walls.at(0).motion;
  EXPECT_EQ(motion.type, "planetary");
  EXPECT_EQ(motion.centre, Vec3(0.8, 0.5, 0.0));
  EXPECT_DOUBLE_EQ(motion.revolution_rpm, -25.0);
  EXPECT_DOUBLE_EQ(motion.ramp_time, 0.0);
}

TEST(CaseMotion, RotationNeedsItsSpeed) {
  const InputError error = load_error(with_wall_motion("      type: rotation\n"));
  EXPECT_THAT(error.what(), HasSubstr("walls[0].motion"));
  EXPECT_THAT(error.what(), HasSubstr("rpm"));
}

TEST(CaseMotion, UnknownMotionTypeListsTheKnownOnes) {
  const InputError error = load_error(with_wall_motion("      type: wobble\n"));
  EXPECT_THAT(error.what(), HasSubstr("walls[0].motion.type"));
  EXPECT_THAT(error.what(), HasSubstr("planetary"));
}

TEST(CaseMotion, FixedWallRejectsASpeed) {
  const InputError error = load_error(with_wall_motion("      type: fixed\n      rpm: 10\n"));
  EXPECT_THAT(error.what(), HasSubstr("rpm"));
}

}  // namespace
}  // namespace partimix::case_test
