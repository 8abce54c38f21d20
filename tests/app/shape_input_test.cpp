// `partimix check` on cases with a solid plate and a mesh wall: a good case passes; a missing or
// broken mesh and a solid wall with open faces exit with code 2 and one line naming the case
// file, line and key, and write nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cli_support.hpp"
#include "support/box_mesh.hpp"
#include "support/stl_files.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// A 3D vessel with a solid plate (walls[0], lines 18-24) and a mesh baffle (walls[1], line 25).
const std::string kStirred = R"(solver: sph
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.1, -0.1, -0.1]
  max: [0.3, 0.3, 0.3]
time:
  end: 0.1
  output_interval: 0.05
sph:
  spacing: 0.02
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}
walls:
  - shape: plate
    centre: [0.1, 0.1]
    length: 0.1
    width: 0.04
    height: 0.1
    clearance: 0.02
    solid: true
  - shape: mesh
    file: baffle.stl
    solid: true
)";

// Writes the case and a closed baffle mesh beside it, and runs `partimix check`.
Outcome check(const Scratch& scratch, const std::string& text, const std::string& mesh) {
  scratch.write("case.yaml", text);
  scratch.write("baffle.stl", mesh);
  return run_partimix(scratch, {"check", "case.yaml"});
}

std::string baffle() {
  return test_support::binary_stl(
      test_support::box_triangles(Vec3(0.0, 0.0, 0.0), Vec3(0.2, 0.04, 0.2)), "baffle");
}

TEST(ShapeInput, SolidPlateAndMeshCaseIsValid) {
  const Scratch scratch;
  const Outcome outcome = check(scratch, kStirred, baffle());
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("case.yaml: valid ("));
}

TEST(ShapeInput, BrokenMeshNamesTheCaseFileLineAndKey) {
  const Scratch scratch;
  const Outcome outcome = check(scratch, kStirred, baffle().substr(0, 200));
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, StartsWith("error: case.yaml:26:11: walls[1].file: cannot use the "
                                      "mesh: baffle.stl: "));
  EXPECT_THAT(outcome.err, HasSubstr("truncated"));
  EXPECT_THAT(scratch.work_entries(), ElementsAre("baffle.stl", "case.yaml"));
}

TEST(ShapeInput, SolidWallWithOpenFacesNamesTheKey) {
  const Scratch scratch;
  const Outcome outcome = check(scratch,
                                replaced(kStirred, "    solid: true\n  - shape: mesh",
                                         "    solid: true\n    open: [z+]\n  - shape: mesh"),
                                baffle());
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, StartsWith("error: case.yaml:25:11: walls[0].open: a solid wall"));
}

}  // namespace
}  // namespace partimix::cli_test
