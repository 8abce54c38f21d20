// The running least-squares line (docs/mixing.md, "Mass in a region and discharge rate"): points
// on a line give its slope; the points (0, 1), (1, 3), (2, 2), (3, 5) give
//   b = sum dx dy / sum dx^2 = 5.5 / 5 = 1.1   (x_mean = 1.5, y_mean = 2.75),
// and so do the same points shifted to x = 1e6 + 0..3 (no cancellation at late times); fewer
// than two points, or points at one x, have no slope.
#include "analysis/running_line_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace partimix::analysis {
namespace {

TEST(RunningLineFit, PointsOnALineGiveItsSlope) {
  RunningLineFit fit;
  for (int i = 0; i < 7; ++i)
    fit.add(0.25 * i, 3.0 - 1.5 * 0.25 * i);
  EXPECT_EQ(fit.count(), 7);
  EXPECT_NEAR(fit.slope(), -1.5, 1e-14);
}

TEST(RunningLineFit, ScatteredPointsGiveTheLeastSquaresSlope) {
  for (const double offset : {0.0, 1.0e6}) {
    RunningLineFit fit;
    const double y[] = {1.0, 3.0, 2.0, 5.0};
    for (int i = 0; i < 4; ++i)
      fit.add(offset + i, y[i]);
    // Relative round-off of the shifted x: about 1e-16 x 1e6 per point.
    EXPECT_NEAR(fit.slope(), 1.1, offset == 0.0 ? 1e-15 : 1e-9) << offset;
  }
}

TEST(RunningLineFit, NoSlopeWithoutTwoDistinctTimes) {
  RunningLineFit fit;
  EXPECT_TRUE(std::isnan(fit.slope()));
  fit.add(2.0, 1.0);
  EXPECT_TRUE(std::isnan(fit.slope()));
  fit.add(2.0, 3.0);
  EXPECT_TRUE(std::isnan(fit.slope()));
}

}  // namespace
}  // namespace partimix::analysis
