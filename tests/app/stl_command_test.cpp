// `partimix stl`: a truck drum wall as a binary STL that reads back as the wall's own triangles;
// a case without a generated wall writes nothing; a bad case is exit code 2 with nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cli_support.hpp"
#include "geometry/stl_reader.hpp"
#include "io/case.hpp"
#include "support/small_truck_drum_case.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string& kDrumCase = test_support::kSmallTruckDrumCase;

TEST(StlCommand, WritesTheTruckDrumsTriangles) {
  const Scratch scratch;
  scratch.write("case.yaml", kDrumCase);
  const Outcome outcome = run_partimix(scratch, {"stl", "case.yaml", "-o", "geometry"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("walls[0]:"));
  const geometry::TriangleSoup written =
      geometry::read_stl((scratch.work() / "geometry" / "wall_0.stl").string());
  const geometry::TriangleSoup expected =
      io::load_case((scratch.work() / "case.yaml").string()).walls.at(0).shape->triangles();
  ASSERT_EQ(written.size(), expected.size());
  double largest = 0.0;
  for (std::size_t t = 0; t < written.size(); ++t)
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, (written[t].corner[c] - expected[t].corner[c]).norm());
  EXPECT_LT(largest, 1e-7);  // float coordinates of a 0.2 m drum
  EXPECT_THAT(scratch.work_entries(), ElementsAre("case.yaml", "geometry"));
}

TEST(StlCommand, ABadCaseIsExitTwoAndWritesNothing) {
  const Scratch scratch;
  scratch.write("case.yaml", replaced(kDrumCase, "helix_angle: 78", "helix_angle: 90"));
  const Outcome outcome = run_partimix(scratch, {"stl", "case.yaml", "-o", "geometry"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.err, HasSubstr("walls[0].blades.helix_angle"));
  EXPECT_THAT(scratch.work_entries(), ElementsAre("case.yaml"));
}

TEST(StlCommand, ACaseWithoutAGeneratedWallWritesNothing) {
  const Scratch scratch;
  const std::string plane_only = kDrumCase.substr(0, kDrumCase.find("  - shape: truck_drum")) +
                                 "  - {shape: plane, point: [0, 0, -0.15], normal: [0, 0, 1]}\n";
  scratch.write("case.yaml", plane_only);
  const Outcome outcome = run_partimix(scratch, {"stl", "case.yaml", "-o", "geometry"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("nothing written"));
  EXPECT_THAT(scratch.work_entries(), ElementsAre("case.yaml"));
}

}  // namespace
}  // namespace partimix::cli_test
