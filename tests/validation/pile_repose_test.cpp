// A settled pile's angle of repose rises with friction (cases/pile_repose.yaml: a column of 600
// spheres collapses into a half-heap against a wall; elastic-plastic rolling resistance).
//
// Zhou et al. (Phys. Rev. E 64 (2001) 021301) find, for monosized spheres, that the angle of
// repose rises with the sliding friction mu_s and with the rolling friction mu_r, and that
// without either no heap forms. The test runs mu_s = 0.1, 0.3, 0.6 at mu_r = 0.3 (the same for
// wall contacts) and mu_r = 0.1 at mu_s = 0.6; measured 3.3, 22.4, 27.5 and 14.2 deg
// (docs/dem.md, "Tests"). It asserts
//   - each rise in mu_s and in mu_r raises the angle by more than 2 deg,
//   - at mu_s = 0.1 the column spreads flat (below 10 deg),
//   - at mu_s = 0.6, mu_r = 0.3 the heap stands between 20 and 40 deg, the range of dry
//     granular piles: a band of plausibility, not a comparison with an experiment.
#include <gtest/gtest.h>

#include <string>

#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kMinimumRise = 2.0;  // deg

double pile_angle(double sliding, double rolling) {
  const std::string file = std::string(PARTIMIX_SOURCE_DIR) + "/cases/pile_repose.yaml";
  const std::string mu = std::to_string(sliding);
  const std::string mu_r = std::to_string(rolling);
  const io::Case the_case =
      io::load_case(file, {"output.frames=false", "dem.interactions.particle.friction=" + mu,
                           "dem.interactions.wall.friction=" + mu,
                           "dem.interactions.particle.rolling_friction=" + mu_r,
                           "dem.interactions.wall.rolling_friction=" + mu_r});
  const test_support::CaseRun run = test_support::run_case(the_case);
  EXPECT_EQ(run.summary.status, "completed");
  return run.figures.at("angle_of_repose_final");
}

TEST(PileRepose, AngleRisesWithSlidingAndRollingFriction) {
  const double smooth = pile_angle(0.1, 0.3);
  const double medium = pile_angle(0.3, 0.3);
  const double rough = pile_angle(0.6, 0.3);
  const double rolls_easily = pile_angle(0.6, 0.1);
  EXPECT_LT(smooth, 10.0);
  EXPECT_GT(medium, smooth + kMinimumRise);
  EXPECT_GT(rough, medium + kMinimumRise);
  EXPECT_GT(rough, rolls_easily + kMinimumRise);
  EXPECT_GT(rough, 20.0);
  EXPECT_LT(rough, 40.0);
}

}  // namespace
}  // namespace partimix
