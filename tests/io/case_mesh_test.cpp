// shape: mesh (docs/case-reference.md, "Shapes"): a closed triangle mesh from an STL file beside
// the case file (or at an absolute path), scaled and offset, as a wall or a fluid region; every
// problem with the mesh is an InputError about the item's `file` key that quotes the mesh's own.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "case_files.hpp"
#include "geometry/triangle_check.hpp"
#include "support/box_mesh.hpp"
#include "support/sph_case.hpp"
#include "support/stl_files.hpp"

namespace partimix::case_test {
namespace {

using test_support::ascii_stl;
using test_support::binary_stl;
using test_support::box_triangles;
using ::testing::HasSubstr;

// A valid 3D case whose fluid region is the text of line 15 on.
std::string case_3d(const std::string& region) {
  return R"(solver: sph
dimensions: 3
domain:
  min: [-0.5, -0.5, -0.5]
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
)" + region;
}

const std::string kBoxRegion =
    "    - shape: box\n      min: [0, 0, 0]\n      max: [0.2, 0.2, 0.2]\n";

// case_3d with a box region and a mesh wall from `file` (line 20), with `more` lines after it.
std::string with_mesh_wall(const std::string& file, const std::string& more = "") {
  return case_3d(kBoxRegion) + "walls:\n  - shape: mesh\n    file: " + file + "\n" + more;
}

// A cube of 100 mm as drawn in millimetres.
std::string cube_mm() {
  return binary_stl(box_triangles(Vec3::Zero(), Vec3(100.0, 100.0, 100.0)), "cube");
}

TEST(CaseMesh, WallMeshBesideTheCaseFileIsScaledThenOffset) {
  const CaseFile file(with_mesh_wall(
      "cube.stl", "    scale: 0.001\n    offset: [0.1, -0.05, 0]\n    solid: true\n"));
  file.add_file("cube.stl", cube_mm());
  const io::Case loaded = io::load_case(file.path());
  const geometry::Shape& shape = *loaded.walls.at(0).shape;
  EXPECT_TRUE(shape.lower().isApprox(Vec3(0.1, -0.05, 0.0), 1e-12)) << shape.lower().transpose();
  EXPECT_TRUE(shape.upper().isApprox(Vec3(0.2, 0.05, 0.1), 1e-12)) << shape.upper().transpose();
  EXPECT_NEAR(shape.signed_distance(Vec3(0.15, 0.0, 0.05)), -0.05, 1e-12);
  EXPECT_TRUE(loaded.walls.at(0).solid);
  EXPECT_EQ(loaded.resolved["walls"][0]["file"], "cube.stl");
}

TEST(CaseMesh, ScaleAndOffsetDefaultToNone) {
  const CaseFile file(with_mesh_wall("cube.stl"));
  file.add_file("cube.stl", ascii_stl(box_triangles(Vec3::Zero(), Vec3::Constant(0.1)), "c"));
  const io::Case loaded = io::load_case(file.path());
  EXPECT_EQ(loaded.walls.at(0).shape->upper(), Vec3::Constant(0.1));
  EXPECT_EQ(loaded.resolved["walls"][0]["scale"], 1.0);
  EXPECT_EQ(loaded.resolved["walls"][0]["offset"], nlohmann::json::array({0.0, 0.0, 0.0}));
}

TEST(CaseMesh, AbsolutePathIsTakenAsIs) {
  const test_support::TempDir elsewhere("partimix_mesh");
  const std::string mesh = (elsewhere / "cube.stl").string();
  std::ofstream(mesh, std::ios::binary) << cube_mm();
  const io::Case loaded = load_text(with_mesh_wall(mesh, "    scale: 0.001\n"));
  EXPECT_TRUE(loaded.walls.at(0).shape->upper().isApprox(Vec3::Constant(0.1), 1e-12));
}

TEST(CaseMesh, FluidRegionCanBeAMesh) {
  const CaseFile file(case_3d("    - shape: mesh\n      file: cube.stl\n      scale: 0.001\n"));
  file.add_file("cube.stl", cube_mm());
  const io::Case loaded = io::load_case(file.path());
  EXPECT_TRUE(test_support::fluid_of(loaded).regions.at(0).shape->upper().isApprox(
      Vec3::Constant(0.1), 1e-12));
}

TEST(CaseMesh, MissingFileNamesTheCaseFileLineAndKey) {
  const InputError error = load_error(with_mesh_wall("nowhere.stl"));
  expect_location(error, "case.yaml", 20, 11, "walls[0].file");
  EXPECT_THAT(error.message(), HasSubstr("cannot use the mesh: "));
  EXPECT_THAT(error.message(), HasSubstr("nowhere.stl"));
  EXPECT_THAT(error.message(), HasSubstr("cannot read"));
}

TEST(CaseMesh, OpenMeshIsAnErrorAboutTheFileKey) {
  geometry::TriangleSoup open = box_triangles(Vec3::Zero(), Vec3::Constant(0.1));
  open.pop_back();
  const CaseFile file(with_mesh_wall("open.stl"));
  file.add_file("open.stl", binary_stl(open, "open"));
  const InputError error = load_error(file);
  expect_location(error, "case.yaml", 20, 11, "walls[0].file");
  EXPECT_THAT(error.message(), HasSubstr("open.stl"));
  EXPECT_THAT(error.message(), HasSubstr("not closed"));
}

// Triangles without area: a repeated corner, and three corners on a line.
geometry::TriangleSoup flat_triangles() {
  geometry::Triangle repeated{{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)}};
  geometry::Triangle on_a_line{{Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5), Vec3(1, 1, 1)}};
  return {repeated, on_a_line};
}

// One check for every method (issue 15: DEM accepted a mesh that SPH refused).
TEST(CaseMesh, AMeshOfOnlyDegenerateTrianglesIsRefusedForEveryMethod) {
  const std::string dem_case = R"(solver: dem
dimensions: 3
domain: {min: [-1, -1, -1], max: [1, 1, 1]}
time: {end: 1.0, output_interval: 0.1}
dem:
  species: [{name: a, density: 2500, youngs_modulus: 1.0e7, poisson_ratio: 0.3}]
  fill: {region: {shape: box, min: [0, 0, 0], max: [0.1, 0.1, 0.1]}, count: 1, radius: 0.01}
walls:
  - shape: mesh
    file: flat.stl
)";
  for (const std::string& text : {with_mesh_wall("flat.stl"), dem_case}) {
    const CaseFile file(text);
    file.add_file("flat.stl", ascii_stl(flat_triangles(), "flat"));
    const InputError error = load_error(file);
    EXPECT_EQ(error.location().key_path, "walls[0].file");
    EXPECT_THAT(error.message(), HasSubstr("none of its 2 triangles has an area"));
  }
}

TEST(CaseMesh, DegenerateTrianglesAmongGoodOnesAreDropped) {
  geometry::TriangleSoup cube = box_triangles(Vec3::Zero(), Vec3::Constant(0.1));
  const std::size_t good = cube.size();
  for (const geometry::Triangle& flat : flat_triangles())
    cube.push_back(flat);
  const CaseFile file(with_mesh_wall("cube.stl"));
  file.add_file("cube.stl", ascii_stl(cube, "cube"));
  EXPECT_NO_THROW(io::load_case(file.path()));
  EXPECT_EQ(geometry::checked_triangles(cube, Vec3::Zero()).size(), good);
}

TEST(CaseMesh, MalformedStlQuotesItsOwnLine) {
  const CaseFile file(with_mesh_wall("bad.stl"));
  file.add_file("bad.stl", "solid bad\n  facet normal 0 0 0\n    outer loop\n      vertex 0 0\n");
  const InputError error = load_error(file);
  expect_location(error, "case.yaml", 20, 11, "walls[0].file");
  EXPECT_THAT(error.message(), HasSubstr("bad.stl:4:"));
}

TEST(CaseMesh, ProblemInAFluidRegionMeshNamesThatKey) {
  const InputError error = load_error(case_3d("    - shape: mesh\n      file: nowhere.stl\n"));
  expect_location(error, "case.yaml", 16, 13, "fluid.regions[0].file");
  EXPECT_THAT(error.message(), HasSubstr("cannot read"));
}

TEST(CaseMesh, ScaleMustBePositive) {
  const InputError error = load_error(with_mesh_wall("cube.stl", "    scale: 0\n"));
  expect_location(error, "case.yaml", 21, 12, "walls[0].scale");
  EXPECT_EQ(error.message(), "must be > 0, got 0");
}

TEST(CaseMesh, FileIsRequired) {
  const InputError error = load_error(case_3d("    - shape: mesh\n      scale: 2\n"));
  EXPECT_EQ(error.location().key_path, "fluid.regions[0].file");
  EXPECT_EQ(error.message(), "missing required key 'file'");
}

TEST(CaseMesh, In2DIsAnError) {
  const InputError error = load_error(kMinimal2D + "walls:\n  - shape: mesh\n    file: cube.stl\n");
  expect_location(error, "case.yaml", 19, 12, "walls[0].shape");
  EXPECT_THAT(error.message(), HasSubstr("mesh needs dimensions: 3"));
}

}  // namespace
}  // namespace partimix::case_test
