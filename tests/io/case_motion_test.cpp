// walls[].motion: each wall is a body with a prescribed motion (docs/case-reference.md,
// "walls"); the keys load with their defaults, and bad ones are InputErrors naming the key (and
// its line and column where the tests give them).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

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

TEST(CaseMotion, TranslationLoads) {
  const io::Case loaded = load_text(with_wall_motion(R"(      type: translation
      velocity: [0, 0.5]
      start: 0.1
      stop: 0.4
)"));
  const geometry::MotionConfig& motion = loaded.walls.at(0).motion;
  EXPECT_EQ(motion.type, "translation");
  EXPECT_EQ(motion.velocity, Vec3(0.0, 0.5, 0.0));
  EXPECT_DOUBLE_EQ(motion.start, 0.1);
  EXPECT_DOUBLE_EQ(motion.stop, 0.4);
  EXPECT_EQ(loaded.resolved["walls"][0]["motion"]["stop"], 0.4);
}

TEST(CaseMotion, TranslationStartsAtZeroAndNeverStopsByDefault) {
  const io::Case loaded =
      load_text(with_wall_motion("      type: translation\n      velocity: [0, 0.5]\n"));
  const geometry::MotionConfig& motion = loaded.walls.at(0).motion;
  EXPECT_EQ(motion.start, 0.0);
  EXPECT_EQ(motion.stop, std::numeric_limits<double>::infinity());
  const auto& resolved = loaded.resolved["walls"][0]["motion"];
  EXPECT_EQ(resolved["start"], 0.0);
  EXPECT_EQ(resolved["stop"], "auto");
  EXPECT_FALSE(resolved.contains("rpm"));
}

TEST(CaseMotion, TranslationNeedsItsVelocity) {
  const InputError error = load_error(with_wall_motion("      type: translation\n"));
  EXPECT_EQ(error.location().key_path, "walls[0].motion.velocity") << error.what();
  EXPECT_THAT(error.message(), HasSubstr("missing required key 'velocity'"));
}

TEST(CaseMotion, TranslationStopsAfterItStarts) {
  // The motion's first key is on line 23 (kMinimal2D has 17 lines).
  const InputError error = load_error(with_wall_motion(
      "      type: translation\n      velocity: [0, 1]\n      start: 0.2\n      stop: 0.2\n"));
  expect_location(error, "case.yaml", 26, 13, "walls[0].motion.stop");
  EXPECT_THAT(error.message(), HasSubstr("stop must be later than start"));
  const InputError negative = load_error(
      with_wall_motion("      type: translation\n      velocity: [0, 1]\n      start: -1\n"));
  expect_location(negative, "case.yaml", 25, 14, "walls[0].motion.start");
}

TEST(CaseMotion, TranslationTakesNoSpeedInRpm) {
  const InputError error = load_error(
      with_wall_motion("      type: translation\n      velocity: [0, 1]\n      rpm: 5\n"));
  expect_location(error, "case.yaml", 25, 7, "walls[0].motion.rpm");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'rpm'"));
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
