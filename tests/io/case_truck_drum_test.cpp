// A truck drum wall (docs/case-reference.md, "Shapes", truck_drum) and a rotation's speed
// schedule (docs/case-reference.md, "walls[].motion"): they load into the drum's parameters (the
// angles from degrees) and the schedule, and bad values are InputErrors at their keys.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "case_files.hpp"
#include "geometry/truck_drum_shape.hpp"
#include "support/small_truck_drum_case.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

const std::string kDemHead = test_support::kSmallTruckDrumCase;

const std::string kSchedule = R"(    motion:
      type: rotation
      axis_point: [-0.1, 0, 0]
      axis: [1, 0, 0.2]
      rpm: 14
      ramp_time: 1
      schedule:
        - {time: 5, rpm: 0}
        - {time: 8, rpm: -8}
)";

TEST(CaseTruckDrum, LoadsWithItsAnglesInDegreesAndAScheduledRotation) {
  const io::Case loaded = load_text(kDemHead + kSchedule);
  const auto* drum = dynamic_cast<const geometry::TruckDrumShape*>(loaded.walls.at(0).shape.get());
  ASSERT_NE(drum, nullptr);
  const geometry::TruckDrumParameters& p = drum->drum().parameters();
  constexpr double degree = std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(p.helix_angle, 78.0 * degree);
  EXPECT_DOUBLE_EQ(p.offset_angles[2], 76.0 * degree);
  EXPECT_DOUBLE_EQ(p.blade_thickness, 0.004);
  EXPECT_DOUBLE_EQ(drum->drum().length(), 0.17);
  EXPECT_FALSE(drum->triangles().empty());
  ASSERT_TRUE(loaded.walls.at(0).surface);
  const geometry::MotionConfig& motion = loaded.walls.at(0).motion;
  ASSERT_EQ(motion.schedule.size(), 2u);
  EXPECT_DOUBLE_EQ(motion.schedule[1].time, 8.0);
  EXPECT_DOUBLE_EQ(motion.schedule[1].rpm, -8.0);
}

std::string key_of_error(const std::string& text) {
  return load_error(CaseFile(text)).location().key_path;
}

TEST(CaseTruckDrum, BadValuesAreLocated) {
  EXPECT_EQ(key_of_error(replace_line(kDemHead, 27,
                                      "    blades: {height: 0.02, thickness: 0.004, "
                                      "helix_angle: 95, offset_angles: [100, 85, 76]}")),
            "walls[0].blades.helix_angle");
  EXPECT_EQ(key_of_error(replace_line(kDemHead, 27,
                                      "    blades: {height: 0.02, thickness: 0.004, "
                                      "helix_angle: 70, offset_angles: [100, 85]}")),
            "walls[0].blades.offset_angles");
  EXPECT_EQ(key_of_error(replace_line(kDemHead, 21, "    head_radius: -1")),
            "walls[0].head_radius");
  EXPECT_EQ(key_of_error(replace_line(kDemHead, 28, "    divisions: 5")), "walls[0].divisions");
  EXPECT_EQ(key_of_error(replace_line(kDemHead, 20, "    axis: [0, 0, 0]")), "walls[0].axis");
  const InputError wide = load_error(CaseFile(replace_line(kDemHead, 21, "    head_radius: 0.1")));
  EXPECT_EQ(wide.location().key_path, "walls[0].shape");
  EXPECT_THAT(wide.message(), HasSubstr("head_radius must not exceed radius"));
  const InputError thin = load_error(CaseFile(replace_line(
      kDemHead, 27,
      "    blades: {height: 0.02, thickness: 1.0e-12, helix_angle: 89.99999, offset_angles: [0, "
      "0, 0]}")));
  EXPECT_EQ(thin.location().key_path, "walls[0].shape");
  EXPECT_THAT(thin.message(), HasSubstr("turn too far"));
  const std::string back_in_time = kDemHead + R"(    motion:
      type: rotation
      rpm: 14
      schedule:
        - {time: 5, rpm: 0}
        - {time: 5, rpm: -8}
)";
  EXPECT_EQ(key_of_error(back_in_time), "walls[0].motion.schedule[1].time");
}

TEST(CaseTruckDrum, ItsAnalysesLoadAndNeedADrumTurningAboutItsAxis) {
  const std::string analyses = R"(analyses:
  - {type: drum_segregation, wall: 0, coarse_species: 0, bins: 8, threshold: 4, mixing_until: 5, average_from: 4}
  - {type: drum_discharge, wall: 0, fit_from: 8, fit_until: 12}
)";
  const io::Case loaded = load_text(kDemHead + kSchedule + analyses);
  ASSERT_EQ(loaded.analyses.size(), 2u);
  EXPECT_EQ(loaded.analyses[0].drum_measures.bins, 8);
  EXPECT_DOUBLE_EQ(loaded.analyses[0].drum_measures.mixing_until, 5.0);
  EXPECT_DOUBLE_EQ(loaded.analyses[0].drum_measures.average_from, 4.0);
  EXPECT_DOUBLE_EQ(loaded.analyses[1].drum_measures.fit_until, 12.0);
  EXPECT_EQ(loaded.analyses[1].drum_measures.drum.get(), loaded.walls[0].shape.get());
  const std::string off_axis =
      R"(    motion: {type: rotation, axis_point: [-0.1, 0.01, 0], axis: [1, 0, 0.2], rpm: 14}
)";
  EXPECT_EQ(key_of_error(kDemHead + off_axis + analyses), "analyses[0].wall");
  const std::string plane = "  - {shape: plane, point: [0, 0, -0.15], normal: [0, 0, 1]}\n";
  EXPECT_EQ(key_of_error(kDemHead + plane +
                         replace_line(analyses, 2, "  - {type: drum_segregation, wall: 1}")),
            "analyses[0].wall");
  EXPECT_EQ(
      key_of_error(kDemHead +
                   replace_line(analyses, 3,
                                "  - {type: drum_discharge, wall: 0, fit_from: 8, fit_until: 8}")),
      "analyses[1].fit_until");
  EXPECT_EQ(key_of_error(kDemHead + replace_line(analyses, 2,
                                                 "  - {type: drum_segregation, wall: 0, "
                                                 "mixing_until: 5, average_from: 6}")),
            "analyses[0].average_from");
}

TEST(CaseTruckDrum, NeedsThreeDimensions) {
  const InputError error = load_error(CaseFile(kMinimal2D + R"(walls:
  - {shape: truck_drum, axis_point: [0, 0], axis: [1, 0]}
)"));
  EXPECT_THAT(error.message(), HasSubstr("truck_drum needs dimensions: 3"));
}

}  // namespace
}  // namespace partimix::case_test
