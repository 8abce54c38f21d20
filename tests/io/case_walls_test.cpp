// The shared walls section (docs/case-reference.md, "walls"): every shape makes both a shape for
// SPH and a surface for DEM; the DEM reads its walls from it, with each wall's material; the
// old `dem.walls` is refused with the place the walls now go.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "case_files.hpp"
#include "dem/dem_section.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

const std::string kDemHead = R"(solver: dem
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.2, -0.2, -0.2]
  max: [0.2, 0.2, 0.2]
time:
  end: 0.1
  output_interval: 0.01
dem:
  species:
    - {name: a, density: 2500}
    - {name: b, density: 2500}
  interactions:
    wall: {restitution: 0.6, friction: 0.4, rolling_friction: 0.02}
  fill:
    region: {shape: box, min: [-0.05, -0.05, 0.0], max: [0.05, 0.05, 0.05]}
    count: 10
    radius: 0.005
)";

std::string dem_case(const std::string& walls) {
  return kDemHead + "walls:\n" + walls;
}

const dem::Config& dem_config(const io::Case& c) {
  return c.section<dem::DemSection>("dem").config;
}

TEST(CaseWalls, EveryShapeGivesASurfaceAndTheDemItsWalls) {
  const io::Case loaded = load_text(
      dem_case(R"(  - {shape: box, min: [-0.1, -0.1, -0.1], max: [0.1, 0.1, 0.1], open: [z+]}
  - {shape: cylinder, center: [0, 0, -0.1], radius: 0.1, height: 0.2, open: [z+]}
  - {shape: plane, point: [0, 0, -0.1], normal: [0, 0, 1]}
  - {shape: drum, axis_point: [0, 0, 0], axis: [1, 0, 0], radius: 0.15}
  - {shape: cone, axis_point: [0, 0, -0.1], axis: [0, 0, 1], radius_0: 0.02, radius_1: 0.1, height: 0.1}
  - {shape: plate, centre: [0, 0], length: 0.05, width: 0.01, height: 0.05, solid: true}
)"));
  ASSERT_EQ(loaded.walls.size(), 6u);
  ASSERT_EQ(dem_config(loaded).walls.size(), 6u);
  for (std::size_t w = 0; w < loaded.walls.size(); ++w) {
    ASSERT_TRUE(loaded.walls[w].shape) << w;
    ASSERT_TRUE(loaded.walls[w].surface) << w;
    EXPECT_EQ(dem_config(loaded).walls[w].surface, loaded.walls[w].surface) << w;
  }
  // A grain resting on the floor of the box touches it: gap = its height above the floor.
  geometry::SurfacePoint contact;
  ASSERT_TRUE(loaded.walls[0].surface->nearest(Vec3(0.0, 0.0, -0.095), 0.01, contact));
  EXPECT_NEAR(contact.gap, 0.005, 1e-12);
  EXPECT_NEAR(contact.normal.z(), 1.0, 1e-12);
}

TEST(CaseWalls, MaterialGivesTheElasticConstantsAndOverridesTheInteractions) {
  const io::Case loaded = load_text(dem_case(R"(  - shape: plane
    point: [0, 0, -0.1]
    normal: [0, 0, 1]
    material: {youngs_modulus: 5.0e6, poisson_ratio: 0.25, friction: 0.9}
  - {shape: plane, point: [0, 0, 0.1], normal: [0, 0, -1]}
)"));
  const dem::Config& config = dem_config(loaded);
  EXPECT_DOUBLE_EQ(config.walls[0].material.youngs_modulus, 5.0e6);
  EXPECT_DOUBLE_EQ(config.walls[0].material.poisson_ratio, 0.25);
  for (std::size_t species = 0; species < 2; ++species) {
    EXPECT_DOUBLE_EQ(config.wall_interaction(0, species).friction, 0.9);
    EXPECT_DOUBLE_EQ(config.wall_interaction(0, species).restitution, 0.6);
    EXPECT_DOUBLE_EQ(config.wall_interaction(0, species).rolling_friction, 0.02);
    EXPECT_DOUBLE_EQ(config.wall_interaction(1, species).friction, 0.4);
  }
  EXPECT_DOUBLE_EQ(config.walls[1].material.youngs_modulus, 2.0e11);
}

TEST(CaseWalls, OldDemWallsSayWhereTheWallsGo) {
  std::string text = kDemHead;
  text.insert(text.find("  fill:"),
              "  walls:\n    - {surface: plane, point: [0, 0, 0], "
              "normal: [0, 0, 1]}\n");
  const InputError error = load_error(text);
  expect_location(error, "case.yaml", 17, 5, "dem.walls");
  EXPECT_THAT(error.message(), HasSubstr("top-level `walls:`"));
  EXPECT_THAT(error.message(), HasSubstr("`shape:` in place of `surface:`"));
}

TEST(CaseWalls, PlaneDrumAndConeHaveNoSolidOrOpenFaces) {
  const InputError error = load_error(
      dem_case("  - {shape: plane, point: [0, 0, 0], normal: [0, 0, 1], solid: true}\n"));
  EXPECT_EQ(error.location().key_path, "walls[0].solid");
  EXPECT_THAT(error.message(), HasSubstr("its sides are fixed"));
  const InputError open = load_error(dem_case(
      "  - {shape: drum, axis_point: [0, 0, 0], axis: [1, 0, 0], radius: 0.1, open: [x+]}\n"));
  EXPECT_EQ(open.location().key_path, "walls[0].open");
}

TEST(CaseWalls, BadWallValuesAreLocated) {
  EXPECT_EQ(load_error(dem_case("  - {shape: plane, point: [0, 0, 0], normal: [0, 0, 0]}\n"))
                .location()
                .key_path,
            "walls[0].normal");
  EXPECT_EQ(load_error(dem_case("  - {shape: drum, axis_point: [0, 0, 0], axis: [0, 0, 0], "
                                "radius: 0.1}\n"))
                .location()
                .key_path,
            "walls[0].axis");
  EXPECT_EQ(load_error(dem_case("  - {shape: plane, point: [0, 0, 0], normal: [0, 0, 1], "
                                "material: {restitution: 1.5}}\n"))
                .location()
                .key_path,
            "walls[0].material.restitution");
  EXPECT_EQ(load_error(dem_case("  - {shape: cone, axis_point: [0, 0, 0], axis: [0, 0, 1], "
                                "radius_0: 0, radius_1: 0, height: 0.1}\n"))
                .location()
                .key_path,
            "walls[0].radius_1");
}

TEST(CaseWalls, DrumAndConeNeedThreeDimensions) {
  const InputError error = load_error(kMinimal2D +
                                      "walls:\n  - {shape: drum, axis_point: [0, 0], axis: [1, 0], "
                                      "radius: 1}\n");
  EXPECT_THAT(error.message(), HasSubstr("drum needs dimensions: 3"));
}

}  // namespace
}  // namespace partimix::case_test
