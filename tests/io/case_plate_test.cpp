// walls[].solid and shape: plate (docs/case-reference.md, "Shapes" and "walls"): a plate is the
// box of a flat-plate impeller, standing `clearance` above the floor in 3D; a solid wall has no
// open faces; bad keys are InputErrors naming the line and key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_files.hpp"
#include "support/sph_case.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

// A valid 3D case; walls added after line 17.
const std::string kMinimal3D = R"(solver: sph
dimensions: 3
domain:
  min: [-0.5, -0.5, -0.1]
  max: [0.5, 0.5, 0.5]
time:
  end: 1.0
  output_interval: 0.1
sph:
  spacing: 0.01
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [-0.1, -0.1, 0]
      max: [0.1, 0.1, 0.3]
)";

// kMinimal3D with one plate wall (lines 18-23) and `more` lines after it.
std::string with_plate_3d(const std::string& more = "") {
  return kMinimal3D + R"(walls:
  - shape: plate
    centre: [0.01, 0.02]
    length: 0.15
    width: 0.008
    height: 0.37
)" + more;
}

// kMinimal2D with one plate wall (lines 18-22) and `more` lines after it.
std::string with_plate_2d(const std::string& more = "") {
  return kMinimal2D + R"(walls:
  - shape: plate
    centre: [0.8, 0.5]
    length: 0.2
    width: 0.04
)" + more;
}

void expect_bounds(const geometry::Shape& shape, const Vec3& lo, const Vec3& hi) {
  EXPECT_TRUE(shape.lower().isApprox(lo, 1e-12)) << shape.lower().transpose();
  EXPECT_TRUE(shape.upper().isApprox(hi, 1e-12)) << shape.upper().transpose();
}

TEST(CasePlate, In3DStandsClearanceAboveTheFloor) {
  const io::Case loaded =
      load_text(with_plate_3d("    bottom: 0.01\n    clearance: 0.014\n    solid: true\n"));
  const io::WallSpec& wall = loaded.walls.at(0);
  expect_bounds(*wall.shape, Vec3(0.01 - 0.075, 0.02 - 0.004, 0.024),
                Vec3(0.01 + 0.075, 0.02 + 0.004, 0.024 + 0.37));
  EXPECT_TRUE(wall.solid);
  EXPECT_TRUE(wall.open_faces.empty());
  EXPECT_EQ(loaded.resolved["walls"][0]["clearance"], 0.014);
}

TEST(CasePlate, FloorAndClearanceDefaultToZeroAndWallsToContainers) {
  const io::Case loaded = load_text(with_plate_3d());
  expect_bounds(*loaded.walls.at(0).shape, Vec3(-0.065, 0.016, 0.0), Vec3(0.085, 0.024, 0.37));
  EXPECT_FALSE(loaded.walls.at(0).solid);
  EXPECT_EQ(loaded.resolved["walls"][0]["bottom"], 0.0);
  EXPECT_EQ(loaded.resolved["walls"][0]["clearance"], 0.0);
  EXPECT_EQ(loaded.resolved["walls"][0]["solid"], false);
}

TEST(CasePlate, In2DIsTheRectangleAboutItsCentre) {
  const io::Case loaded = load_text(with_plate_2d("    solid: true\n"));
  expect_bounds(*loaded.walls.at(0).shape, Vec3(0.7, 0.48, -1.0), Vec3(0.9, 0.52, 1.0));
  EXPECT_TRUE(loaded.walls.at(0).solid);
}

TEST(CasePlate, IsAlsoAFluidRegionShape) {
  const io::Case loaded =
      load_text(replace_line(remove_line(remove_line(kMinimal2D, 17), 16), 15,
                             "    - {shape: plate, centre: [0.25, 0.5], length: 0.5, width: 1.0}"));
  expect_bounds(*test_support::fluid_of(loaded).regions.at(0).shape, Vec3(0.0, 0.0, -1.0),
                Vec3(0.5, 1.0, 1.0));
}

TEST(CasePlate, HeightIn2DIsAnErrorNamingTheKey) {
  const InputError error = load_error(with_plate_2d("    height: 0.3\n"));
  expect_location(error, "case.yaml", 23, 13, "walls[0].height");
  EXPECT_EQ(error.message(), "applies to a plate in 3D only (dimensions is 2)");
}

TEST(CasePlate, ClearanceIn2DIsAnErrorNamingTheKey) {
  const InputError error = load_error(with_plate_2d("    clearance: 0.01\n"));
  expect_location(error, "case.yaml", 23, 16, "walls[0].clearance");
}

TEST(CasePlate, NonPositiveLengthIsAnError) {
  const InputError error = load_error(replace_line(with_plate_3d(), 21, "    length: 0"));
  expect_location(error, "case.yaml", 21, 13, "walls[0].length");
  EXPECT_EQ(error.message(), "must be > 0, got 0");
}

TEST(CasePlate, NegativeClearanceIsAnError) {
  const InputError error = load_error(with_plate_3d("    clearance: -0.01\n"));
  expect_location(error, "case.yaml", 24, 16, "walls[0].clearance");
  EXPECT_EQ(error.message(), "must be >= 0, got -0.01");
}

TEST(CasePlate, HeightIsRequiredIn3D) {
  const InputError error = load_error(remove_line(with_plate_3d(), 23));
  expect_location(error, "case.yaml", 19, 5, "walls[0].height");
  EXPECT_EQ(error.message(), "missing required key 'height'");
}

TEST(CasePlate, CentreHasTwoComponents) {
  const InputError error = load_error(replace_line(with_plate_3d(), 20, "    centre: [0, 0, 0]"));
  expect_location(error, "case.yaml", 20, 13, "walls[0].centre");
  EXPECT_THAT(error.message(), HasSubstr("expected 2 components"));
}

TEST(CaseSolidWall, OpenFacesAreAnErrorNamingTheKey) {
  const InputError error = load_error(with_plate_2d("    solid: true\n    open: [y+]\n"));
  expect_location(error, "case.yaml", 24, 11, "walls[0].open");
  EXPECT_THAT(error.message(), HasSubstr("solid wall (solid: true) has no open faces"));
}

TEST(CaseSolidWall, SolidIsABool) {
  const InputError error = load_error(with_plate_2d("    solid: maybe\n"));
  expect_location(error, "case.yaml", 23, 12, "walls[0].solid");
  EXPECT_EQ(error.message(), "expected true or false, got 'maybe'");
}

TEST(CaseSolidWall, ABoxCanBeSolid) {
  const io::Case loaded = load_text(kMinimal2D + R"(walls:
  - shape: box
    min: [1, 0.2]
    max: [1.2, 0.4]
    solid: true
)");
  EXPECT_TRUE(loaded.walls.at(0).solid);
}

}  // namespace
}  // namespace partimix::case_test
