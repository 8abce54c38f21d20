// A free surface without gravity is warned about (issue 15: the Youcefi vessel, open and without
// gravity, lost liquid over its rim): a half-filled open box warns, a full closed one does not,
// and gravity silences it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "app/simulation.hpp"
#include "support/case_run.hpp"

namespace partimix::app {
namespace {

using ::testing::HasSubstr;

std::string box_case(const std::string& gravity, const std::string& fill_top,
                     const std::string& open) {
  return "solver: sph\ndimensions: 2\ngravity: " + gravity + R"(
domain: {min: [-0.1, -0.1], max: [0.5, 0.5]}
time: {end: 0.01, output_interval: 0.01}
sph: {spacing: 0.02, max_velocity: 1.0}
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions: [{shape: box, min: [0, 0], max: [0.4, )" +
         fill_top + R"(]}]
walls: [{shape: box, min: [0, 0], max: [0.4, 0.4], open: )" +
         open + "}]\n";
}

std::vector<std::string> warnings_of(const std::string& text) {
  const test_support::TempDir dir;
  return build_simulation(test_support::load_case_text(dir, text)).warnings;
}

TEST(FreeSurfaceWarning, AnOpenHalfFilledBoxWithoutGravityWarns) {
  const auto warnings = warnings_of(box_case("[0, 0]", "0.2", "[y+]"));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("free surface but gravity is zero"));
}

TEST(FreeSurfaceWarning, AFullClosedBoxWithoutGravityDoesNot) {
  EXPECT_TRUE(warnings_of(box_case("[0, 0]", "0.4", "[]")).empty());
}

TEST(FreeSurfaceWarning, GravityHoldsTheSurface) {
  EXPECT_TRUE(warnings_of(box_case("[0, -9.81]", "0.2", "[y+]")).empty());
}

}  // namespace
}  // namespace partimix::app
