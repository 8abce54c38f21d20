// Sampling cells: cylinder rings of equal area give cells of equal volume (analytically, and in
// Monte-Carlo counts), points map to the ring, sector and layer they lie in for any axis, points
// outside give -1, and box cells index x fastest and accept a flat side for 2D runs.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "analysis/sampling_cells.hpp"
#include "support/uniform_random.hpp"

namespace partimix::analysis {
namespace {

using test_support::Uniform;

constexpr double kPi = std::numbers::pi;

// An orthonormal frame (e1, e2, axis) built here independently of CylinderCells.
struct Frame {
  Vec3 e1;
  Vec3 e2;
  Vec3 axis;
};

Frame frame_around(const Vec3& axis) {
  const Vec3 a = axis.normalized();
  const Vec3 e1 = a.unitOrthogonal();
  return {e1, a.cross(e1), a};
}

Vec3 from_cylindrical(const Vec3& origin, const Frame& f, double r, double theta, double z) {
  return origin + z * f.axis + r * (std::cos(theta) * f.e1 + std::sin(theta) * f.e2);
}

CylinderRegion tilted_region() {
  CylinderRegion region;
  region.axis_point = Vec3(0.2, -0.1, 0.4);
  region.axis = Vec3(1.0, 2.0, 2.0) / 3.0;
  region.radius = 0.3;
  region.z0 = -0.1;
  region.z1 = 0.5;
  return region;
}

TEST(CylinderCells, EqualAreaRingsGiveCellsOfEqualVolume) {
  const CylinderRegion region = tilted_region();
  const int n_r = 5, n_theta = 6, n_z = 3;
  const CylinderCells cells(region, n_r, n_theta, n_z);
  ASSERT_EQ(cells.count(), n_r * n_theta * n_z);
  const double height = region.z1 - region.z0;
  const double expected = kPi * region.radius * region.radius * height / cells.count();
  double inner = 0.0;
  for (int ring = 0; ring < n_r; ++ring) {
    const double outer = cells.ring_outer_radius(ring);
    const double volume = kPi * (outer * outer - inner * inner) / n_theta * height / n_z;
    // Only round-off separates the cell volumes: a few ulps of r^2 = R^2 (k + 1) / n_r.
    EXPECT_NEAR(volume / expected, 1.0, 1e-12) << "ring " << ring;
    inner = outer;
  }
  EXPECT_NEAR(cells.ring_outer_radius(n_r - 1), region.radius, 1e-15);
}

// Points drawn uniformly in a cylinder a little larger than the region, in a frame built here:
// those inside must land in a cell, those outside give -1, and the counts per cell must be
// equal up to sampling noise.
TEST(CylinderCells, MonteCarloCountsPerCellAreEqualAndOutsidePointsGiveMinusOne) {
  const CylinderRegion region = tilted_region();
  const CylinderCells cells(region, 4, 6, 3);
  const Frame f = frame_around(region.axis);
  const int per_cell = 5000;
  const int n = cells.count();
  std::vector<int> counts(static_cast<std::size_t>(n), 0);
  Uniform uniform(20240601);
  const double r_max = 1.2 * region.radius;
  const double z_lo = region.z0 - 0.1, z_hi = region.z1 + 0.1;
  int inside = 0;
  while (inside < per_cell * n) {
    const double r = r_max * std::sqrt(uniform());
    const double theta = 2.0 * kPi * uniform();
    const double z = z_lo + (z_hi - z_lo) * uniform();
    const int cell = cells.cell_of(from_cylindrical(region.axis_point, f, r, theta, z));
    const bool in_region = r < region.radius && z > region.z0 && z < region.z1;
    ASSERT_EQ(cell >= 0, in_region) << "r " << r << " z " << z;
    if (!in_region)
      continue;
    ASSERT_LT(cell, n);
    ++counts[static_cast<std::size_t>(cell)];
    ++inside;
  }
  // Counts are multinomial with equal probabilities 1/n: Pearson's chi^2 has mean n - 1 and
  // standard deviation sqrt(2 (n - 1)); each count has standard deviation sqrt(N (1/n)(1 - 1/n)).
  // Both are held to five standard deviations (a false alarm below 1e-4 over all cells, and
  // the seed is fixed). Rings of equal width instead of equal area would hold 1/16, 3/16, 5/16
  // and 7/16 of the points: thousands of counts, tens of sigma, away.
  const double expected = per_cell;
  const double sigma = std::sqrt(expected * (1.0 - 1.0 / n));
  double chi2 = 0.0;
  for (int c = 0; c < n; ++c) {
    const double deviation = counts[static_cast<std::size_t>(c)] - expected;
    EXPECT_LT(std::abs(deviation), 5.0 * sigma) << "cell " << c;
    chi2 += deviation * deviation / expected;
  }
  EXPECT_LT(chi2, (n - 1) + 5.0 * std::sqrt(2.0 * (n - 1)));
}

TEST(CylinderCells, PointsOutsideGiveMinusOne) {
  const CylinderRegion region = tilted_region();
  const CylinderCells cells(region, 3, 4, 2);
  const Frame f = frame_around(region.axis);
  const Vec3& o = region.axis_point;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(cells.cell_of(from_cylindrical(o, f, 1.0001 * region.radius, 1.0, 0.2)), -1);
  EXPECT_EQ(cells.cell_of(from_cylindrical(o, f, 0.1, 1.0, region.z0 - 1e-9)), -1);
  EXPECT_EQ(cells.cell_of(from_cylindrical(o, f, 0.1, 1.0, region.z1 + 1e-9)), -1);
  EXPECT_EQ(cells.cell_of(Vec3(nan, 0.0, 0.0)), -1);
  EXPECT_GE(cells.cell_of(from_cylindrical(o, f, 0.1, 1.0, 0.2)), 0);
}

TEST(CylinderCells, BoundaryBelongsToTheOutermostRingAndTheEndLayers) {
  CylinderRegion region;
  region.radius = 2.0;
  region.z0 = 1.0;
  region.z1 = 3.0;
  const int n_r = 3, n_theta = 4, n_z = 2;
  const CylinderCells cells(region, n_r, n_theta, n_z);
  // On the axis (theta = 0, ring 0) at the bottom face, and on the rim at the top face.
  EXPECT_EQ(cells.cell_of(Vec3(0.0, 0.0, 1.0)), 0);
  const int top_rim = ((n_z - 1) * n_theta + 0) * n_r + (n_r - 1);
  EXPECT_EQ(cells.cell_of(Vec3(2.0, 0.0, 3.0)), top_rim);
}

// For an axis along z the angle is measured from x towards y, so the half y < 0 (the seed's
// red half) is exactly the upper half of the sectors when n_theta is even.
TEST(CylinderCells, AlongZTheAngleRunsFromXTowardsY) {
  const CylinderCells cells(CylinderRegion{}, 1, 4, 1);
  EXPECT_TRUE(cells.reference().isApprox(Vec3::UnitX()));
  EXPECT_EQ(cells.cell_of(Vec3(0.5, 0.1, 0.5)), 0);
  EXPECT_EQ(cells.cell_of(Vec3(-0.1, 0.5, 0.5)), 1);
  EXPECT_EQ(cells.cell_of(Vec3(-0.5, -0.1, 0.5)), 2);
  EXPECT_EQ(cells.cell_of(Vec3(0.1, -0.5, 0.5)), 3);
}

// Along x and along a tilted axis, a point built from (ring, sector, layer) centres in the
// frame CylinderCells reports lands in the cell of that (ring, sector, layer).
void expect_cells_follow_the_frame(const CylinderRegion& region) {
  const int n_r = 3, n_theta = 5, n_z = 4;
  const CylinderCells cells(region, n_r, n_theta, n_z);
  const Vec3 e1 = cells.reference();
  EXPECT_NEAR(e1.norm(), 1.0, 1e-14);
  EXPECT_NEAR(e1.dot(cells.axis()), 0.0, 1e-14);
  const Frame f{e1, cells.axis().cross(e1), cells.axis()};
  const double height = region.z1 - region.z0;
  for (int layer = 0; layer < n_z; ++layer) {
    for (int sector = 0; sector < n_theta; ++sector) {
      for (int ring = 0; ring < n_r; ++ring) {
        const double r = region.radius * std::sqrt((ring + 0.5) / n_r);
        const double theta = 2.0 * kPi * (sector + 0.5) / n_theta;
        const double z = region.z0 + height * (layer + 0.5) / n_z;
        const Vec3 x = from_cylindrical(region.axis_point, f, r, theta, z);
        EXPECT_EQ(cells.cell_of(x), (layer * n_theta + sector) * n_r + ring);
      }
    }
  }
}

TEST(CylinderCells, AxisAlongXMapsRingSectorAndLayer) {
  CylinderRegion region;
  region.axis_point = Vec3(-1.0, 0.5, 0.25);
  region.axis = Vec3::UnitX();
  region.radius = 0.4;
  region.z0 = 0.0;
  region.z1 = 2.0;
  expect_cells_follow_the_frame(region);
}

TEST(CylinderCells, TiltedAxisMapsRingSectorAndLayer) {
  expect_cells_follow_the_frame(tilted_region());
}

TEST(CylinderCells, AxisIsNormalised) {
  CylinderRegion scaled = tilted_region();
  scaled.axis *= 7.0;
  const CylinderCells a(tilted_region(), 2, 3, 2);
  const CylinderCells b(scaled, 2, 3, 2);
  const Vec3 x = tilted_region().axis_point + Vec3(0.05, -0.02, 0.2);
  EXPECT_EQ(a.cell_of(x), b.cell_of(x));
  EXPECT_NEAR(b.axis().norm(), 1.0, 1e-15);
}

TEST(CylinderCells, RejectsBadGeometry) {
  CylinderRegion zero_axis;
  zero_axis.axis = Vec3::Zero();
  EXPECT_THROW(CylinderCells(zero_axis, 1, 1, 1), std::invalid_argument);
  CylinderRegion no_radius;
  no_radius.radius = 0.0;
  EXPECT_THROW(CylinderCells(no_radius, 1, 1, 1), std::invalid_argument);
  CylinderRegion inverted;
  inverted.z0 = 1.0;
  inverted.z1 = 1.0;
  EXPECT_THROW(CylinderCells(inverted, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(CylinderCells(CylinderRegion{}, 0, 1, 1), std::invalid_argument);
  EXPECT_THROW(CylinderCells(CylinderRegion{}, 1, 0, 1), std::invalid_argument);
  EXPECT_THROW(CylinderCells(CylinderRegion{}, 1, 1, 0), std::invalid_argument);
}

TEST(BoxCells, IndexRunsXFastest) {
  const BoxCells cells(Vec3(0.0, 0.0, 0.0), Vec3(2.0, 3.0, 4.0), {2, 3, 4});
  ASSERT_EQ(cells.count(), 24);
  for (int iz = 0; iz < 4; ++iz)
    for (int iy = 0; iy < 3; ++iy)
      for (int ix = 0; ix < 2; ++ix)
        EXPECT_EQ(cells.cell_of(Vec3(ix + 0.5, iy + 0.5, iz + 0.5)), (iz * 3 + iy) * 2 + ix);
  EXPECT_EQ(cells.cell_of(Vec3(2.0, 3.0, 4.0)), 23);
  EXPECT_EQ(cells.cell_of(Vec3(0.0, 0.0, 0.0)), 0);
}

TEST(BoxCells, PointsOutsideGiveMinusOne) {
  const BoxCells cells(Vec3(-1.0, -1.0, -1.0), Vec3(1.0, 1.0, 1.0), {2, 2, 2});
  EXPECT_EQ(cells.cell_of(Vec3(1.0 + 1e-12, 0.0, 0.0)), -1);
  EXPECT_EQ(cells.cell_of(Vec3(0.0, -1.0 - 1e-12, 0.0)), -1);
  EXPECT_EQ(cells.cell_of(Vec3(0.0, 0.0, 5.0)), -1);
  EXPECT_EQ(cells.cell_of(Vec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0)), -1);
}

TEST(BoxCells, AFlatSideWithOneDivisionServes2DRuns) {
  const BoxCells cells(Vec3(0.0, 0.0, 0.0), Vec3(1.0, 1.0, 0.0), {4, 4, 1});
  EXPECT_EQ(cells.count(), 16);
  EXPECT_EQ(cells.cell_of(Vec3(0.9, 0.3, 0.0)), 1 * 4 + 3);
  EXPECT_EQ(cells.cell_of(Vec3(0.9, 0.3, 1e-9)), -1);
}

TEST(BoxCells, RejectsBadGeometry) {
  EXPECT_THROW(BoxCells(Vec3::Zero(), Vec3(1.0, -1.0, 1.0), {1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(BoxCells(Vec3::Zero(), Vec3(1.0, 1.0, 0.0), {1, 1, 2}), std::invalid_argument);
  EXPECT_THROW(BoxCells(Vec3::Zero(), Vec3::Ones(), {1, 0, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace partimix::analysis
