// The analysis orientation_order (docs/case-reference.md, "analyses"): the reference direction
// is the grains' velocity by default or a direction (normalised), with min_speed and a rotating
// frame {axis_point, axis, rpm} for the velocity only; a method without grains that have an axis
// (spheres only) is refused at the analysis' type, with file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "case_files.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

// A DEM case of one species with `species_keys`, filled with 10 grains, then the analyses
// list `items`: the first item is line kFirstItem.
std::string dem_case(const std::string& species_keys, const std::string& items) {
  return R"(solver: dem
dimensions: 3
domain: {min: [-1, -1, -1], max: [1, 1, 1]}
time: {end: 1.0, output_interval: 0.1}
dem:
  species:
    - {name: a, density: 2500)" +
         species_keys + R"(}
  fill:
    region: {shape: box, min: [-0.5, -0.5, -0.5], max: [0.5, 0.5, 0.5]}
    count: 10
analyses:
)" + items;
}
constexpr int kFirstItem = 12;
constexpr double kPi = std::numbers::pi;
const std::string kProlate = ", shape: {half_axes: [0.001, 0.001, 0.003]}";

const analysis::OrientationReference& reference_of(const io::Case& loaded) {
  EXPECT_EQ(loaded.analyses.size(), 1u);
  return loaded.analyses.at(0).orientation;
}

TEST(CaseOrientationOrder, TheVelocityByDefault) {
  const io::Case loaded = load_text(dem_case(kProlate, "  - type: orientation_order\n"));
  EXPECT_EQ(loaded.analyses.at(0).type, "orientation_order");
  EXPECT_TRUE(reference_of(loaded).velocity);
  EXPECT_EQ(reference_of(loaded).min_speed, 0.0);
  EXPECT_EQ(loaded.resolved["analyses"][0]["direction"], "velocity");
  EXPECT_EQ(loaded.resolved["analyses"][0]["min_speed"], 0.0);
  const io::Case slow = load_text(
      dem_case(kProlate, "  - {type: orientation_order, direction: velocity, min_speed: 0.01}\n"));
  EXPECT_EQ(reference_of(slow).min_speed, 0.01);
}

TEST(CaseOrientationOrder, ADirectionIsNormalised) {
  const io::Case loaded =
      load_text(dem_case(kProlate, "  - {type: orientation_order, direction: [0, 3, 4]}\n"));
  EXPECT_FALSE(reference_of(loaded).velocity);
  EXPECT_EQ(reference_of(loaded).direction, Vec3(0.0, 0.6, 0.8));
}

TEST(CaseOrientationOrder, ARotatingFrameTurnsAtItsRpm) {
  const io::Case loaded =
      load_text(dem_case(kProlate,
                         "  - type: orientation_order\n    rotating_frame: {axis_point: [0, 1, 0], "
                         "axis: [0, 0, 2], rpm: 30}\n"));
  EXPECT_TRUE(reference_of(loaded).rotating_frame);
  EXPECT_EQ(reference_of(loaded).frame_point, Vec3(0.0, 1.0, 0.0));
  EXPECT_LT((reference_of(loaded).frame_angular_velocity - Vec3(0.0, 0.0, kPi)).norm(), 1e-15);
  EXPECT_FALSE(
      reference_of(load_text(dem_case(kProlate, "  - type: orientation_order\n"))).rotating_frame);
}

TEST(CaseOrientationOrder, SpheresAloneAreRefusedAtTheType) {
  const InputError error = load_error(R"(solver: dem
dimensions: 3
domain: {min: [-1, -1, -1], max: [1, 1, 1]}
time: {end: 1.0, output_interval: 0.1}
dem:
  species:
    - {name: a, density: 2500}
  fill:
    region: {shape: box, min: [-0.5, -0.5, -0.5], max: [0.5, 0.5, 0.5]}
    count: 10
    radius: 0.01
analyses:
  - type: orientation_order
)");
  expect_location(error, "case.yaml", 13, 11, "analyses[0].type");
  EXPECT_THAT(error.message(), HasSubstr("needs grains with an axis"));
}

TEST(CaseOrientationOrder, EqualHalfAxesHaveNoAxisEither) {
  const InputError error =
      load_error(dem_case(", shape: {half_axes: [0.002, 0.002, 0.002], blockiness: [4, 4]}",
                          "  - type: orientation_order\n"));
  expect_location(error, "case.yaml", kFirstItem, 11, "analyses[0].type");
}

TEST(CaseOrientationOrder, BadReferencesAreLocated) {
  struct Bad {
    std::string item;
    int line;
    int column;
    std::string key;
    std::string message;
  };
  for (const Bad& bad : {
           Bad{"  - type: orientation_order\n    direction: flow\n", kFirstItem + 1, 16,
               "analyses[0].direction", "expected the word velocity or a direction"},
           Bad{"  - type: orientation_order\n    direction: [0, 0, 0]\n", kFirstItem + 1, 16,
               "analyses[0].direction", "expected the word velocity or a direction"},
           Bad{"  - type: orientation_order\n    direction: [1, 0, 0]\n    min_speed: 0.1\n",
               kFirstItem + 2, 16, "analyses[0].min_speed", "applies with direction: velocity"},
           Bad{"  - type: orientation_order\n    min_speed: -1\n", kFirstItem + 1, 16,
               "analyses[0].min_speed", ""},
           Bad{"  - type: orientation_order\n    direction: [1, 0, 0]\n    rotating_frame: "
               "{axis_point: [0, 0, 0], axis: [0, 0, 1], rpm: 30}\n",
               kFirstItem + 2, 21, "analyses[0].rotating_frame",
               "applies with direction: velocity"},
           Bad{"  - type: orientation_order\n    rotating_frame: {axis_point: [0, 0, 0], axis: [0, "
               "0, 0], rpm: 30}\n",
               kFirstItem + 1, 51, "analyses[0].rotating_frame.axis", "expected a direction"},
           Bad{"  - type: orientation_order\n    rotating_frame: {axis_point: [0, 0, 0], axis: [0, "
               "0, 1]}\n",
               kFirstItem + 1, 21, "analyses[0].rotating_frame.rpm", ""},
       }) {
    const InputError error = load_error(dem_case(kProlate, bad.item));
    expect_location(error, "case.yaml", bad.line, bad.column, bad.key);
    EXPECT_THAT(error.message(), HasSubstr(bad.message)) << bad.item;
  }
}

}  // namespace
}  // namespace partimix::case_test
