// The droplet analysis' pure measures (docs/multi-material-sph.md, "The scheme", droplet
// measurements): the outline diameter of rings and spherical shells whose surfaces lie half a
// layer beyond their outermost and innermost particles (four layers of 1 between radii 10 and 14:
// particles at 10.5 and 13.5, D = 28), invalid input NaN; a spacing-equivalent is the d-th root
// of the volume; weighted means, medians (NaN with a value not finite) and the sample nearest a
// time by hand; and a shell's surfaces from distances and spacings: inner within half a spacing
// of the smallest distance, outer within half a spacing of the largest.
#include "analysis/droplet_measures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace partimix::analysis {
namespace {

constexpr double kTight = 1e-14;

TEST(DropletMeasures, OutlineDiameterOfARingAndASphericalShell) {
  const double ring = std::numbers::pi * (14.0 * 14.0 - 10.0 * 10.0);
  EXPECT_NEAR(outline_diameter(10.5, 13.5, ring, 2), 28.0, 28.0 * kTight);
  const double shell = 4.0 / 3.0 * std::numbers::pi * (14.0 * 14.0 * 14.0 - 10.0 * 10.0 * 10.0);
  EXPECT_NEAR(outline_diameter(10.5, 13.5, shell, 3), 28.0, 28.0 * kTight);
  // Stretched layers 0.25 thick: the particles at 10.125 and 10.875 of a ring from 10 to 11.
  const double thin = 4.0 / 3.0 * std::numbers::pi * (11.0 * 11.0 * 11.0 - 10.0 * 10.0 * 10.0);
  EXPECT_NEAR(outline_diameter(10.125, 10.875, thin, 3), 22.0, 22.0 * kTight);
  // One layer: inner and outer alike.
  EXPECT_NEAR(outline_diameter(5.0, 5.0, std::numbers::pi * (5.5 * 5.5 - 4.5 * 4.5), 2), 11.0,
              11.0 * kTight);
}

TEST(DropletMeasures, OutlineDiameterOfInvalidInputIsNaN) {
  EXPECT_TRUE(std::isnan(outline_diameter(0.0, 1.0, 1.0, 2)));
  EXPECT_TRUE(std::isnan(outline_diameter(2.0, 1.0, 1.0, 2)));
  EXPECT_TRUE(std::isnan(outline_diameter(1.0, 2.0, 0.0, 3)));
  EXPECT_TRUE(std::isnan(outline_diameter(std::nan(""), 2.0, 1.0, 3)));
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

TEST(DropletMeasures, WeightedMedianByHandAndNaNWithoutPairs) {
  std::vector<std::pair<double, double>> pairs;
  EXPECT_TRUE(std::isnan(weighted_median(pairs)));
  // A thin layer far off moves the mean (to 169) but not the median.
  pairs = {{500.0, 0.1}, {150.0, 0.5}, {140.0, 0.3}, {20.0, 0.1}};
  EXPECT_EQ(weighted_median(pairs), 150.0);
  pairs = {{1.0, 1.0}, {3.0, 1.0}};
  EXPECT_EQ(weighted_median(pairs), 1.0);
  pairs = {{1.0, 1.0}, {3.0, 1.5}};
  EXPECT_EQ(weighted_median(pairs), 3.0);
  pairs = {{1.0, 1.0}, {std::nan(""), 1.0}, {3.0, 1.0}};
  EXPECT_TRUE(std::isnan(weighted_median(pairs)));
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
