// Solid walls in a built simulation (docs/geometry-meshes.md, "Solid walls"): the fluid clears
// a solid plate by half a spacing, the plate's particles are one body, a mesh cube gives the
// same particles as the equal box, and a plate too thin for the lattice is an InputError.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "app/simulation.hpp"
#include "core/error.hpp"
#include "geometry/lattice.hpp"
#include "io/case.hpp"
#include "support/box_mesh.hpp"
#include "support/stl_files.hpp"
#include "support/temp_dir.hpp"

namespace partimix::app {
namespace {

using ::testing::HasSubstr;

// The plate of tank_with_plate(0.06).
const geometry::Box kPlate(Vec3(0.405, 0.27, -1.0), Vec3(0.605, 0.33, 1.0));

// A 2D tank [0, 1] x [0, 1] (open top) with water to 0.6 m, spacing 0.02, and the solid plate
// 0.2 x `width` about (0.505, 0.3) as walls[1].
std::string tank_with_plate(double width) {
  return R"(solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.1, -0.1]
  max: [1.1, 1.1]
time:
  end: 0.1
  output_interval: 0.05
sph:
  spacing: 0.02
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: box, min: [0, 0], max: [1, 0.6]}
walls:
  - {shape: box, min: [0, 0], max: [1, 1], open: [y+]}
  - shape: plate
    centre: [0.505, 0.3]
    length: 0.2
    width: )" +
         std::to_string(width) + "\n    solid: true\n";
}

// A 3D fluid cube [0, 0.2]^3 at spacing 0.02 with one solid wall given by `wall` (one line).
// The wall [0.065, 0.145]^3 keeps every fluid lattice point clear of the half-spacing tie.
std::string cube_case(const std::string& wall) {
  return R"(solver: sph
dimensions: 3
domain:
  min: [-0.1, -0.1, -0.1]
  max: [0.3, 0.3, 0.3]
time:
  end: 0.1
  output_interval: 0.05
sph:
  spacing: 0.02
  max_velocity: 1
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}
walls:
  - )" + wall +
         "\n";
}

Simulation build(const test_support::TempDir& folder, const std::string& text) {
  std::ofstream(folder / "case.yaml") << text;
  return build_simulation(io::load_case((folder / "case.yaml").string()));
}

std::vector<std::int32_t> bodies_of(const Simulation& simulation) {
  return simulation.methods[0].store->find_integer("body")->values;
}

// The positions of the fluid (or wall) particles, sorted.
std::vector<std::array<double, 3>> positions(const ParticleStore& store, bool fluid) {
  std::vector<std::array<double, 3>> points;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (store.is_fluid(i) == fluid) {
      const Vec3& x = store.position()[i];
      points.push_back({x.x(), x.y(), x.z()});
    }
  }
  std::sort(points.begin(), points.end());
  return points;
}

TEST(SolidWall, FluidClearsThePlateByHalfASpacing) {
  const test_support::TempDir folder;
  const Simulation simulation = build(folder, tank_with_plate(0.06));
  const ParticleStore& store = *simulation.methods[0].store;
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (store.is_fluid(i)) {
      ++fluid;
      EXPECT_GE(kPlate.signed_distance(store.position()[i]), 0.5 * 0.02 - 1e-12);
    }
  }
  // The 50 x 30 fill at 0.01 + 0.02 i less the points at x in [0.41, 0.61] (0.61 is 0.005 from
  // the face at 0.605) and y in [0.27, 0.33] (on the faces and inside).
  EXPECT_EQ(fluid, 50u * 30u - 11u * 4u);
}

TEST(SolidWall, PlateParticlesAreOneBody) {
  const test_support::TempDir folder;
  const Simulation simulation = build(folder, tank_with_plate(0.06));
  ASSERT_EQ(simulation.methods[0].bodies->count(), 2u);
  const std::vector<std::int32_t> body = bodies_of(simulation);
  const ParticleStore& store = *simulation.methods[0].store;
  std::size_t in_plate = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const bool inside = kPlate.signed_distance(store.position()[i]) <= 0.0;
    EXPECT_EQ(body[i] == 1, inside) << "particle " << i;
    in_plate += inside ? 1 : 0;
  }
  // Every lattice point of the plate (3 rows of 10): it is thinner than the wall layers.
  EXPECT_EQ(in_plate, 10u * 3u);
}

TEST(SolidWall, PlateThinnerThanHalfASpacingIsAnInputError) {
  const test_support::TempDir folder;
  try {
    build(folder, tank_with_plate(0.008));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().key_path, "walls[1]");
    EXPECT_THAT(error.message(), HasSubstr("no lattice point lies inside this solid wall"));
  }
}

// 2h = 0.06 m at dp = 0.02: a plate 0.06 thick (3 rows, the middle one 0.03 deep) passes; 0.04
// (2 rows 0.01 deep: 0.04 thick by the estimate) and 0.02 (1 row) are seen through.
TEST(SolidWall, PlateThinnerThanTheKernelSupportIsWarnedAbout) {
  const test_support::TempDir folder;
  EXPECT_TRUE(build(folder, tank_with_plate(0.06)).warnings.empty());
  for (const double width : {0.04, 0.02}) {
    const Simulation thin = build(folder, tank_with_plate(width));
    ASSERT_EQ(thin.warnings.size(), 1u) << width;
    EXPECT_THAT(thin.warnings[0], HasSubstr("case.yaml: walls[1] is about"));
    EXPECT_THAT(thin.warnings[0], HasSubstr("less than the kernel support 2h = 0.06 m"));
    EXPECT_THAT(thin.methods[0].load_caveats.at(1), HasSubstr("loads on it come out too small"));
  }
  EXPECT_THAT(build(folder, tank_with_plate(0.04)).warnings[0], HasSubstr("about 0.04 m thick"));
}

TEST(SolidWall, MeshCubeGivesTheParticlesOfTheEqualBox) {
  const Vec3 lo = Vec3::Constant(0.065);
  const Vec3 hi = Vec3::Constant(0.145);
  const test_support::TempDir folder;
  std::ofstream(folder / "cube.stl")
      << test_support::ascii_stl(test_support::box_triangles(lo, hi), "cube");
  const Simulation from_mesh =
      build(folder, cube_case("{shape: mesh, file: cube.stl, solid: true}"));
  const Simulation from_box = build(
      folder, cube_case("{shape: box, min: [0.065, 0.065, 0.065], max: [0.145, 0.145, 0.145], "
                        "solid: true}"));
  const auto walls = positions(*from_mesh.methods[0].store, false);
  EXPECT_EQ(walls.size(), 4u * 4u * 4u);
  EXPECT_EQ(walls, positions(*from_box.methods[0].store, false));
  // Of the fluid lattice points at 0.01 + 0.02 i, those in [0.07, 0.15] on every axis are
  // cleared (inside the cube, or on a face at 0.15 within a spacing of a cube particle at 0.135,
  // docs/geometry-meshes.md) but the 13 on the three edges and the corner where two or three
  // coordinates are 0.15: 0.0218 m and 0.026 m from the nearest cube particle.
  const auto fluid = positions(*from_mesh.methods[0].store, true);
  EXPECT_EQ(fluid.size(), 10u * 10u * 10u - 5u * 5u * 5u + 13u);
  EXPECT_EQ(fluid, positions(*from_box.methods[0].store, true));
}

}  // namespace
}  // namespace partimix::app
