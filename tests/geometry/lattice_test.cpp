// Lattice samplers: fills hold the expected count at the expected spacing and stay inside the
// shape; wall layers lie outside it within the requested thickness, respect open faces and
// periodic axes, and surround the fill so that every fluid particle sees a full kernel of wall.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
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

// Golden rings: the same rings and counts as staggered ones, ring k's first point turned by k
// golden angles (2 pi (2 - phi)), so that no two neighbouring pairs of rings start in the same
// phase.
TEST(Lattice, GoldenRingsTurnEachRingByTheGoldenAngle) {
  const double dp = 0.01;
  LatticeOptions staggered;
  staggered.polar_centre = Vec3(0.5, 0.5, 0.0);
  LatticeOptions golden = staggered;
  golden.golden_rings = true;
  const Cylinder disc(Vec3(0.5, 0.5, -1.0), 0.1, 2.0);
  const std::vector<Vec3> plain = fill(disc, dp, domain_2d(), staggered);
  const std::vector<Vec3> turned = fill(disc, dp, domain_2d(), golden);
  ASSERT_EQ(turned.size(), plain.size());
  const double golden_angle = 2.0 * std::numbers::pi * (2.0 - std::numbers::phi);
  std::size_t first = 0;
  for (int ring = 0; ring < 10; ++ring) {
    const double radius = (ring + 0.5) * dp;
    const long around = std::lround(2.0 * std::numbers::pi * radius / dp);
    const Vec3 offset = turned[first] - *golden.polar_centre;
    EXPECT_NEAR(offset.norm(), radius, 1e-12);
    const double turn = std::atan2(offset.y(), offset.x()) - golden_angle * ring;
    EXPECT_NEAR(std::remainder(turn, 2.0 * std::numbers::pi), 0.0, 1e-12) << "ring " << ring;
    first += static_cast<std::size_t>(around);
  }
}

// A 2D annulus on the polar lattice about its centre (the Taylor-Couette set-up): the fluid
// fills rings at R_in + (k + 1/2) dp, k = 0..9, each of round(2 pi r / dp) points, and the wall
// rings lie at R_out + (k + 1/2) dp outside and R_in - (k + 1/2) dp inside.
TEST(Lattice, PolarLatticeLaysAnAnnulusOnRings) {
  const double dp = 0.01;
  const double inner = 0.1;
  const double outer = 0.2;
  LatticeOptions polar;
  polar.polar_centre = Vec3(0.5, 0.5, 0.0);
  const Cylinder outer_circle(Vec3(0.5, 0.5, -1.0), outer, 2.0);
  const Cylinder inner_circle(Vec3(0.5, 0.5, -1.0), inner, 2.0);
  std::vector<Vec3> fluid = fill(outer_circle, dp, domain_2d(), polar);
  std::erase_if(fluid, [&](const Vec3& x) { return inner_circle.signed_distance(x) < 0.0; });
  std::size_t expected = 0;
  for (int k = 0; k < 10; ++k)
    expected += std::lround(2.0 * std::numbers::pi * (inner + (k + 0.5) * dp) / dp);
  EXPECT_EQ(fluid.size(), expected);
  for (const Vec3& x : fluid) {
    const double r = (x - *polar.polar_centre).norm();
    const double rings = (r - inner) / dp - 0.5;
    EXPECT_NEAR(rings, std::round(rings), 1e-9) << "off the rings at r = " << r;
  }
  const auto outside = wall_layers(outer_circle, dp, 3, {}, domain_2d(), polar);
  const auto inside = inside_layers(inner_circle, dp, 3, domain_2d(), polar);
  for (const auto* walls : {&outside, &inside}) {
    ASSERT_FALSE(walls->empty());
    for (const Vec3& x : *walls) {
      const double r = (x - *polar.polar_centre).norm();
      EXPECT_NEAR(r / dp - 0.5, std::round(r / dp - 0.5), 1e-9);
    }
  }
}

TEST(Lattice, APolarLatticeStaysWithinTheShapesBox) {
  LatticeOptions polar;
  polar.polar_centre = Vec3(0.0, 0.0, 0.0);
  const Box box(Vec3(0.5, 0.5, -1.0), Vec3(0.7, 0.6, 1.0));
  const auto points = fill(box, 0.01, domain_2d(), polar);
  ASSERT_FALSE(points.empty());
  for (const Vec3& x : points)
    EXPECT_LT(box.signed_distance(x), 0.0);
}

// Past a limit the sampler refuses before it allocates (issue 15: a 4294967296 m wide wall
// allocated until memory ran out).
TEST(Lattice, LimitsAreRefusedBeforeAllocating) {
  Domain d = domain_2d();
  d.hi = Vec3(5e9, 2.0, 0.0);
  const Box huge(Vec3(0.0, 0.0, -1.0), Vec3(4294967296.0, 1.0, 1.0));
  EXPECT_THROW(wall_layers(huge, 0.01, 3, {Face{1, 1}}, d), InputError);
  LatticeOptions few;
  few.points = 10;
  const Box box(Vec3(0.0, 0.0, -1.0), Vec3(1.0, 0.5, 1.0));
  try {
    fill(box, 0.1, domain_2d(), few);
    FAIL() << "50 points passed a limit of 10";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("more than limits.particles = 10"), std::string::npos);
  }
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
