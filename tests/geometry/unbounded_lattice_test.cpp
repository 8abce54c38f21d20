// Lattice samplers on the plane, drum and cone shapes (geometry/lattice.hpp): infinite (and
// huge) bounds are cut at the domain, layers behind a plane keep its phase, a drum's wall layers
// fill the domain along its axis, and a cone's wall layers stop at its open rims for a tilted axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/cone.hpp"
#include "geometry/drum.hpp"
#include "geometry/lattice.hpp"
#include "geometry/plane.hpp"

namespace partimix::geometry {
namespace {

constexpr double kTolerance = 1e-12;

Domain box_domain(const Vec3& lo, const Vec3& hi) {
  Domain d;
  d.lo = lo;
  d.hi = hi;
  return d;
}

TEST(UnboundedLattice, InsideLayersOfAnAxisAlignedPlaneSpanTheDomainBehindIt) {
  const double dp = 0.1;
  const Plane floor(Vec3(0.0, 0.0, 0.3), Vec3::UnitZ());
  const Domain domain = box_domain(Vec3::Zero(), Vec3(1.0, 0.5, 1.0));
  const auto points = inside_layers(floor, dp, 2, domain);
  // 10 x 5 points per layer, the layers at 0.5 and 1.5 spacings behind the plane.
  ASSERT_EQ(points.size(), 10u * 5u * 2u);
  for (const Vec3& x : points) {
    EXPECT_TRUE(domain.contains(x));
    EXPECT_TRUE(std::abs(x.z() - 0.25) < kTolerance || std::abs(x.z() - 0.15) < kTolerance)
        << x.transpose();
  }
}

TEST(UnboundedLattice, InsideLayersOfATiltedPlaneSpanTheDomain) {
  const double dp = 0.1;
  const Vec3 normal = Vec3(1.0, 1.0, 1.0).normalized();
  // Placed so that no lattice point lies within 0.01 of either end of the layers.
  const Plane plane(Vec3(0.5, 0.25, 0.53), normal);
  const Domain domain = box_domain(Vec3::Zero(), Vec3(1.0, 0.5, 1.0));
  const auto points = inside_layers(plane, dp, 2, domain);
  // Every point of the domain's lattice within two spacings behind the plane, and no other.
  std::size_t expected = 0;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 5; ++j) {
      for (int k = 0; k < 10; ++k) {
        const Vec3 x = (Vec3(i, j, k) + Vec3::Constant(0.5)) * dp;
        const double d = plane.signed_distance(x);
        expected += (d <= 0.0 && d > -2.0 * dp) ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(points.size(), expected);
  Vec3 lo = Vec3::Constant(1.0);
  Vec3 hi = Vec3::Zero();
  for (const Vec3& x : points) {
    EXPECT_TRUE(domain.contains(x));
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  EXPECT_LT((lo - Vec3::Constant(0.05)).norm(), kTolerance);
  EXPECT_LT((hi - Vec3(0.95, 0.45, 0.95)).norm(), kTolerance);
}

TEST(UnboundedLattice, FillOfATiltedPlaneStaysInTheDomain) {
  const Plane plane(Vec3(0.5, 0.5, 0.52), Vec3(0.0, 1.0, 1.0));
  const Domain domain = box_domain(Vec3::Zero(), Vec3::Ones());
  const auto points = fill(plane, 0.1, domain);
  // Below y + z = 1.02 on the 10 x 10 lattice of y and z: 55 of 100, times 10 along x.
  EXPECT_EQ(points.size(), 550u);
  for (const Vec3& x : points)
    EXPECT_TRUE(domain.contains(x));
}

TEST(UnboundedLattice, HugeBoundsAreCutAtTheDomainAndModestOnesKept) {
  const Domain domain = box_domain(Vec3::Zero(), Vec3::Ones());
  const Box huge(Vec3::Constant(-1e300), Vec3::Constant(1e300));
  EXPECT_EQ(fill(huge, 0.1, domain).size(), 1000u);
  // Poking out by less than the domain's length: the whole box, points outside included.
  const Box poking(Vec3(-0.5, 0.0, 0.0), Vec3(1.0, 1.0, 1.0));
  EXPECT_EQ(fill(poking, 0.1, domain).size(), 1500u);
}

TEST(UnboundedLattice, DrumWallLayersRingTheDrumAlongTheWholeDomain) {
  const double dp = 0.02;
  const double radius = 0.2;
  const Drum drum(Vec3::Zero(), Vec3::UnitZ(), radius);
  const Domain domain = box_domain(Vec3(-0.5, -0.5, 0.0), Vec3(0.5, 0.5, 0.1));
  const auto points = wall_layers(drum, dp, 3, {}, domain);
  // Across the axis the lattice keeps the drum's phase: x = (2 i + 1) 0.01. Count the lattice
  // columns with radius in (R, R + 3 dp), in units of 0.01 (no column lies on either circle).
  std::size_t per_layer = 0;
  for (int i = -25; i <= 25; i += 2) {
    for (int j = -25; j <= 25; j += 2) {
      const int r2 = i * i + j * j;
      per_layer += (r2 > 400 && r2 < 676) ? 1 : 0;
    }
  }
  EXPECT_EQ(points.size(), 5u * per_layer);  // z = 0.01, 0.03, ..., 0.09: inside the domain
  std::set<long> layers;
  for (const Vec3& x : points) {
    const double r = std::hypot(x.x(), x.y());
    EXPECT_GT(r, radius);
    EXPECT_LT(r, radius + 3.0 * dp);
    EXPECT_TRUE(domain.contains(x));
    layers.insert(std::lround(x.z() / 0.01));
  }
  EXPECT_EQ(layers, (std::set<long>{1, 3, 5, 7, 9}));
}

TEST(UnboundedLattice, DrumAlongAPeriodicAxisFillsThePeriod) {
  Domain domain = box_domain(Vec3(-0.3, -0.3, 0.0), Vec3(0.3, 0.3, 0.1));
  domain.periodic = {false, false, true};
  const Drum drum(Vec3::Zero(), Vec3::UnitZ(), 0.2);
  const auto inside = fill(drum, 0.02, domain);
  const auto walls = wall_layers(drum, 0.02, 3, {}, domain);
  EXPECT_FALSE(inside.empty());
  EXPECT_FALSE(walls.empty());
  for (const Vec3& x : inside) {
    EXPECT_LT(drum.signed_distance(x), 0.0);
    EXPECT_TRUE(domain.contains(x));
  }
  // Five layers along z in both.
  EXPECT_EQ(inside.size() % 5, 0u);
  EXPECT_EQ(walls.size() % 5, 0u);
}

TEST(UnboundedLattice, ConeWallLayersStopAtTheRimsOfATiltedCone) {
  const double dp = 0.02;
  const Vec3 base_centre(0.1, -0.05, 0.2);
  const Vec3 axis = Vec3(1.0, 1.0, 2.0).normalized();
  const double height = 0.25;
  const Cone cone(base_centre, Vec3(1.0, 1.0, 2.0), 0.1, 0.2, height);
  const Domain domain = box_domain(Vec3::Constant(-1.0), Vec3::Constant(1.0));
  const auto points = wall_layers(cone, dp, 3, {}, domain);
  ASSERT_FALSE(points.empty());
  bool near_bottom = false;
  bool near_top = false;
  for (const Vec3& x : points) {
    const double d = cone.signed_distance(x);
    EXPECT_GT(d, 0.0);
    EXPECT_LT(d, 3.0 * dp);
    const double z = (x - base_centre).dot(axis);
    EXPECT_GE(z, 0.0);
    EXPECT_LE(z, height);
    near_bottom = near_bottom || z < dp;
    near_top = near_top || z > height - dp;
  }
  EXPECT_TRUE(near_bottom);
  EXPECT_TRUE(near_top);
  // On the same lattice, every point within the layers' thickness outside the frustum that is
  // not beyond a rim is laid, and there are more beyond the rims that are not.
  const Vec3 margin = Vec3::Constant(3.0 * dp);
  const Box around(cone.lower() - margin, cone.upper() + margin);
  std::size_t between_rims = 0;
  std::size_t beyond_rims = 0;
  for (const Vec3& x : fill(around, dp, domain)) {
    const double d = cone.signed_distance(x);
    const double z = (x - base_centre).dot(axis);
    if (d > 0.0 && d < 3.0 * dp)
      ++(z >= 0.0 && z <= height ? between_rims : beyond_rims);
  }
  EXPECT_EQ(between_rims, points.size());
  EXPECT_GT(beyond_rims, 0u);
}

}  // namespace
}  // namespace partimix::geometry
