// The seed's validation drum (cases/drum_validation.yaml: 200 x 20 mm, 1000 spheres of 3.15 mm,
// red left and blue right after settling, 20 rpm) mixes: the Lacey index starts near 0 (the
// halves are segregated: |M| < 0.1) and rises towards 1. Over the first 2 s (2/3 of a
// revolution) a full run reaches M = 0.24 (and 0.50 at 6 s, docs/dem.md, "Cases"); the test
// asserts M > 0.15 at 2 s and a positive fitted exponential rate. The seed's experiment (its
// Fig. 3, ellipsoids) is not available as numbers, so this is a check that the drum mixes at
// all and at a plausible pace, not a comparison with the experiment.
#include <gtest/gtest.h>

#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

TEST(DrumMixing, LaceyIndexRisesFromSegregatedHalves) {
  const std::string file = std::string(PARTIMIX_SOURCE_DIR) + "/cases/drum_validation.yaml";
  const io::Case start = io::load_case(file, {"time.end=0.01"});
  const test_support::CaseRun first = test_support::run_case(start);
  EXPECT_LT(std::abs(first.figures.at("lacey_final")), 0.1);
  const io::Case the_case = io::load_case(file, {"time.end=2.0", "output.frames=false"});
  const test_support::CaseRun run = test_support::run_case(the_case);
  ASSERT_EQ(run.summary.status, "completed");
  EXPECT_GT(run.figures.at("lacey_final"), 0.15);
  EXPECT_GT(run.figures.at("lacey_rate_exp"), 0.0);
}

}  // namespace
}  // namespace partimix
