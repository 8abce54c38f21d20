// The droplet analysis' pure measures (docs/multi-material-sph.md, "The scheme", droplet
// measurements): a disc of area pi has D = 2 and a sphere of volume pi/6 has D = 1; a
// spacing-equivalent is the d-th root of the volume; weighted means and the sample nearest a
// time by hand; and a shell's surfaces from distances and spacings: inner within half a spacing
// of the smallest distance, outer within half a spacing of the largest.
#include "analysis/droplet_measures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace partimix::analysis {
namespace {

constexpr double kTight = 1e-14;

TEST(DropletMeasures, EquivalentDiameterOfADiscAndASphere) {
  EXPECT_NEAR(equivalent_diameter(std::numbers::pi, 2), 2.0, kTight);
  EXPECT_NEAR(equivalent_diameter(std::numbers::pi / 6.0, 3), 1.0, kTight);
  EXPECT_NEAR(equivalent_diameter(4.0 * std::numbers::pi, 2), 4.0, kTight);
}

TEST(DropletMeasures, SpacingEquivalentIsTheRootOfTheVolume) {
  EXPECT_NEAR(spacing_equivalent(0.25, 2), 0.5, kTight);
  EXPECT_NEAR(spacing_equivalent(0.125, 3), 0.5, kTight);
}

TEST(DropletMeasures, WeightedMeanByHandAndNaNWithoutWeight) {
  WeightedMean mean;
  EXPECT_TRUE(std::isnan(mean.value()));
  mean.add(10.0, 1.0);
  mean.add(40.0, 2.0);
  EXPECT_NEAR(mean.value(), 30.0, kTight);
}

TEST(DropletMeasures, NearestSampleWaitsForTheTarget) {
  NearestSample nearest(0.2);
  nearest.add(0.15, 1.0);
  nearest.add(0.18, 2.0);
  EXPECT_FALSE(nearest.reached());
  EXPECT_EQ(nearest.value(), 2.0);
  nearest.add(0.23, 3.0);
  EXPECT_TRUE(nearest.reached());
  EXPECT_EQ(nearest.value(), 2.0);
}

TEST(DropletMeasures, NearestSampleTakesTheEarlierOfTwoAsNear) {
  NearestSample nearest(1.0);
  nearest.add(0.5, 1.0);
  nearest.add(1.5, 2.0);
  EXPECT_TRUE(nearest.reached());
  EXPECT_EQ(nearest.value(), 1.0);
}

// Distances 10 to 13 a spacing apart, and one particle at 10.4 (within half a spacing of the
// inner surface) and one at 12.6 (within half a spacing of the outer).
TEST(DropletMeasures, ShellSurfacesFromDistances) {
  const std::vector<double> distance{10.0, 10.4, 11.0, 12.0, 12.6, 13.0};
  const std::vector<double> spacing(distance.size(), 1.0);
  const std::vector<ShellSurface> expected{ShellSurface::inner, ShellSurface::inner,
                                           ShellSurface::none,  ShellSurface::none,
                                           ShellSurface::outer, ShellSurface::outer};
  EXPECT_EQ(shell_surfaces(distance, spacing), expected);
  EXPECT_TRUE(shell_surfaces({}, {}).empty());
}

// Each particle's own spacing sets its band: a coarse particle at 11 is within its half-spacing
// of the inner distance 10.
TEST(DropletMeasures, EachParticleHasItsOwnBand) {
  const std::vector<double> distance{10.0, 11.0, 13.0};
  const std::vector<double> spacing{1.0, 2.5, 1.0};
  const std::vector<ShellSurface> expected{ShellSurface::inner, ShellSurface::inner,
                                           ShellSurface::outer};
  EXPECT_EQ(shell_surfaces(distance, spacing), expected);
}

}  // namespace
}  // namespace partimix::analysis
