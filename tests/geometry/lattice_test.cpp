// Lattice samplers: fills hold the expected count at the expected spacing and stay inside the
// shape; wall layers lie outside it within the requested thickness, respect open faces and
// periodic axes, and surround the fill so that every fluid particle sees a full kernel of wall.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/lattice.hpp"

namespace partimix::geometry {
namespace {

Domain domain_2d() {
  Domain d;
  d.dimensions = 2;
  d.lo = Vec3(-1.0, -1.0, 0.0);
  d.hi = Vec3(2.0, 2.0, 0.0);
  return d;
}

TEST(Lattice, BoxFillHasOnePointPerCellHalfASpacingFromTheFaces) {
  const Box box(Vec3(0.0, 0.0, -1.0), Vec3(1.0, 0.5, 1.0));
  const auto points = fill(box, 0.1, domain_2d());
  ASSERT_EQ(points.size(), 50u);
  for (const Vec3& x : points) {
    EXPECT_GE(x.x(), 0.05 - 1e-12);
    EXPECT_LE(x.y(), 0.45 + 1e-12);
    EXPECT_EQ(x.z(), 0.0);
  }
}

TEST(Lattice, BoxWallLayersSurroundTheFillExceptTheOpenTop) {
  const double dp = 0.1;
  const Box box(Vec3(0.0, 0.0, -1.0), Vec3(1.0, 1.0, 1.0));
  const auto walls = wall_layers(box, dp, 3, {Face{1, 1}}, domain_2d());
  // Floor 16 x 3 (corners included) and two sides 3 x 10, less the outermost point of each
  // bottom corner: at 3.5 dp from the box it is beyond the three layers (and beyond the reach
  // of any fluid particle inside).
  EXPECT_EQ(walls.size(), 3u * 16u + 2u * 3u * 10u - 2u);
  for (const Vec3& x : walls) {
    EXPECT_GT(box.signed_distance(x), 0.0);
    EXPECT_LT(box.signed_distance(x), 3 * dp);
    EXPECT_LE(x.y(), 1.0);
  }
}

TEST(Lattice, WallsAlongAPeriodicAxisSpanThePeriodOnly) {
  Domain d = domain_2d();
  d.lo.x() = 0.0;
  d.hi.x() = 1.0;
  d.periodic = {true, false, false};
  const Box channel(Vec3(0.0, 0.0, -1.0), Vec3(1.0, 0.5, 1.0));
  const auto walls = wall_layers(channel, 0.1, 3, {}, d);
  EXPECT_EQ(walls.size(), 2u * 3u * 10u);
  for (const Vec3& x : walls) {
    EXPECT_GE(x.x(), 0.0);
    EXPECT_LT(x.x(), 1.0);
  }
}

TEST(Lattice, CylinderFillMatchesItsVolume) {
  Domain d;
  d.lo = Vec3(-1.0, -1.0, -1.0);
  d.hi = Vec3(1.0, 1.0, 1.0);
  const double dp = 0.02;
  const Cylinder cylinder(Vec3(0.0, 0.0, 0.0), 0.3, 0.2);
  const auto points = fill(cylinder, dp, d);
  const double expected = std::numbers::pi * 0.3 * 0.3 * 0.2 / (dp * dp * dp);
  // The staircase of a Cartesian lattice in a circle of 15 spacings: within 2% of the volume.
  EXPECT_NEAR(static_cast<double>(points.size()), expected, 0.02 * expected);
  for (const Vec3& x : points)
    EXPECT_LT(cylinder.signed_distance(x), 0.0);
}

TEST(Lattice, CylinderVesselWallsCoverSideAndBottom) {
  Domain d;
  d.lo = Vec3(-1.0, -1.0, -1.0);
  d.hi = Vec3(1.0, 1.0, 1.0);
  const double dp = 0.02;
  const Cylinder vessel(Vec3(0.0, 0.0, 0.0), 0.3, 0.4);
  const auto walls = wall_layers(vessel, dp, 3, {Face{2, 1}}, d);
  bool bottom = false;
  bool side = false;
  for (const Vec3& x : walls) {
    EXPECT_GT(vessel.signed_distance(x), 0.0);
    EXPECT_LE(x.z(), 0.4);
    bottom = bottom || (x.z() < 0.0 && std::hypot(x.x(), x.y()) < 0.1);
    side = side || (x.z() > 0.2 && std::hypot(x.x(), x.y()) > 0.3);
  }
  EXPECT_TRUE(bottom);
  EXPECT_TRUE(side);
}

TEST(Shapes, SignedDistanceOfBoxAndCylinder) {
  const Box box(Vec3(0.0, 0.0, 0.0), Vec3(1.0, 2.0, 3.0));
  EXPECT_NEAR(box.signed_distance(Vec3(0.5, 1.0, 1.5)), -0.5, 1e-12);
  EXPECT_NEAR(box.signed_distance(Vec3(2.0, 1.0, 1.5)), 1.0, 1e-12);
  EXPECT_NEAR(box.signed_distance(Vec3(2.0, 3.0, 1.5)), std::sqrt(2.0), 1e-12);
  const Cylinder cylinder(Vec3(0.0, 0.0, 0.0), 1.0, 2.0);
  EXPECT_NEAR(cylinder.signed_distance(Vec3(0.0, 0.0, 1.0)), -1.0, 1e-12);
  EXPECT_NEAR(cylinder.signed_distance(Vec3(2.0, 0.0, 1.0)), 1.0, 1e-12);
  EXPECT_NEAR(cylinder.signed_distance(Vec3(0.5, 0.0, -0.5)), 0.5, 1e-12);
}

}  // namespace
}  // namespace partimix::geometry
