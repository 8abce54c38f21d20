// The plane, drum and cone shapes (geometry/plane.hpp, drum.hpp, cone.hpp): signed distance
// (negative inside the solid), bounds (infinite where the shape has no end), open ends, and the
// contact surfaces they make, against values known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/cone.hpp"
#include "geometry/drum.hpp"
#include "geometry/plane.hpp"
#include "geometry/triangle_mesh.hpp"

namespace partimix::geometry {
namespace {

constexpr double kTolerance = 1e-12;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

void expect_near(const Vec3& a, const Vec3& b) {
  EXPECT_LT((a - b).norm(), kTolerance) << a.transpose() << " vs " << b.transpose();
}

TEST(Plane, SignedDistanceIsNegativeBehindThePlane) {
  const Plane plane(Vec3(0.0, 1.0, 0.0), Vec3(0.0, 2.0, 0.0));
  EXPECT_NEAR(plane.signed_distance(Vec3(3.0, 1.5, -2.0)), 0.5, kTolerance);
  EXPECT_NEAR(plane.signed_distance(Vec3(3.0, 0.25, 7.0)), -0.75, kTolerance);
  const Plane tilted(Vec3::Zero(), Vec3(1.0, 1.0, 0.0));
  EXPECT_NEAR(tilted.signed_distance(Vec3(1.0, 1.0, 5.0)), std::sqrt(2.0), kTolerance);
}

TEST(Plane, BoundedOnlyAlongTheAxisItIsNormalTo) {
  const Plane floor(Vec3(0.0, 0.0, 0.3), Vec3::UnitZ());
  EXPECT_EQ(floor.lower(), Vec3::Constant(-kInfinity));
  EXPECT_EQ(floor.upper(), Vec3(kInfinity, kInfinity, 0.3));
  const Plane ceiling(Vec3(0.0, 0.0, 0.3), -Vec3::UnitZ());
  EXPECT_EQ(ceiling.lower(), Vec3(-kInfinity, -kInfinity, 0.3));
  EXPECT_EQ(ceiling.upper(), Vec3::Constant(kInfinity));
  const Plane tilted(Vec3::Zero(), Vec3(0.0, 1.0, 1.0));
  EXPECT_EQ(tilted.lower(), Vec3::Constant(-kInfinity));
  EXPECT_EQ(tilted.upper(), Vec3::Constant(kInfinity));
  EXPECT_FALSE(floor.beyond_open_end(Vec3(0.0, 0.0, 5.0), {Face{2, 1}}));
}

TEST(Drum, SignedDistanceIsTheDistanceFromTheAxisLessTheRadius) {
  const Drum drum(Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 5.0), 0.1);
  EXPECT_NEAR(drum.signed_distance(Vec3(1.0, -0.098, 7.0)), -0.002, kTolerance);
  EXPECT_NEAR(drum.signed_distance(Vec3(1.3, 0.4, -2.0)), 0.4, kTolerance);
  const Drum tilted(Vec3::Zero(), Vec3(1.0, 1.0, 0.0), 1.0);
  EXPECT_NEAR(tilted.signed_distance(Vec3(3.0, 3.0, 0.5)), -0.5, kTolerance);
  EXPECT_NEAR(tilted.signed_distance(Vec3(1.0, -1.0, 0.0)), std::sqrt(2.0) - 1.0, kTolerance);
}

TEST(Drum, BoundedOnlyAcrossItsAxis) {
  const Drum drum(Vec3(1.0, 2.0, 3.0), Vec3::UnitZ(), 0.5);
  EXPECT_EQ(drum.lower(), Vec3(0.5, 1.5, -kInfinity));
  EXPECT_EQ(drum.upper(), Vec3(1.5, 2.5, kInfinity));
  const Drum tilted(Vec3(1.0, 2.0, 3.0), Vec3(1.0, 1.0, 0.0), 0.5);
  EXPECT_EQ(tilted.lower(), Vec3(-kInfinity, -kInfinity, 2.5));
  EXPECT_EQ(tilted.upper(), Vec3(kInfinity, kInfinity, 3.5));
  EXPECT_FALSE(drum.beyond_open_end(Vec3(1.0, 2.0, 100.0), {Face{2, 1}}));
}

// Radius 1 at z = 0 growing to 2 at z = 1 along z: the generator makes 45 degrees with the axis.
Cone hopper() {
  return Cone(Vec3::Zero(), Vec3::UnitZ(), 1.0, 2.0, 1.0);
}

TEST(Cone, SignedDistanceToGeneratorDiscsAndRims) {
  const Cone cone = hopper();
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(cone.signed_distance(Vec3(1.0, 0.0, 0.5)), -0.5 * h, kTolerance);
  EXPECT_NEAR(cone.signed_distance(Vec3(0.0, 2.0, 0.5)), 0.5 * h, kTolerance);
  EXPECT_NEAR(cone.signed_distance(Vec3(0.0, 0.0, 0.1)), -0.1, kTolerance);  // the bottom disc
  EXPECT_NEAR(cone.signed_distance(Vec3(0.0, 0.0, 1.5)), 0.5, kTolerance);   // over the top
  EXPECT_NEAR(cone.signed_distance(Vec3(0.0, 1.0, -0.3)), 0.3, kTolerance);  // under the rim
  EXPECT_NEAR(cone.signed_distance(Vec3(0.0, 2.3, 1.4)), 0.5, kTolerance);   // over the rim
}

TEST(Cone, BoundsAreThoseOfItsRims) {
  const Cone cone = hopper();
  expect_near(cone.lower(), Vec3(-2.0, -2.0, 0.0));
  expect_near(cone.upper(), Vec3(2.0, 2.0, 1.0));
  // Along x: rims of radius 1 at x = 0 and 2 at x = 3, spanning y and z by their radii.
  const Cone sideways(Vec3::Zero(), Vec3(2.0, 0.0, 0.0), 1.0, 2.0, 3.0);
  expect_near(sideways.lower(), Vec3(0.0, -2.0, -2.0));
  expect_near(sideways.upper(), Vec3(3.0, 2.0, 2.0));
}

TEST(Cone, BothRimsAreOpenEndsAlongTheAxis) {
  const Cone tilted(Vec3(1.0, 1.0, 1.0), Vec3(1.0, 0.0, 1.0), 0.5, 1.0, 2.0);
  const Vec3 axis = Vec3(1.0, 0.0, 1.0).normalized();
  const Vec3 across = Vec3(1.0, 0.0, -1.0).normalized();
  EXPECT_TRUE(tilted.beyond_open_end(Vec3(1.0, 1.0, 1.0) - 0.01 * axis + across, {}));
  EXPECT_TRUE(tilted.beyond_open_end(Vec3(1.0, 1.0, 1.0) + 2.01 * axis, {}));
  EXPECT_FALSE(tilted.beyond_open_end(Vec3(1.0, 1.0, 1.0) + 1.99 * axis + 3.0 * across, {}));
}

// The surface of each shape answers as the surface built directly would.
TEST(Shapes, MakeTheirContactSurfaces) {
  SurfacePoint s;
  const Plane floor(Vec3(0.0, 0.0, 0.3), Vec3(0.0, 0.0, 2.0));
  ASSERT_TRUE(floor.make_surface(true, {})->nearest(Vec3(1.0, 2.0, 0.35), 0.1, s));
  EXPECT_NEAR(s.gap, 0.05, kTolerance);
  expect_near(s.normal, Vec3::UnitZ());
  const Drum drum(Vec3::Zero(), Vec3::UnitZ(), 0.1);
  ASSERT_TRUE(drum.make_surface(false, {Face{2, 1}})->nearest(Vec3(0.0, -0.098, 7.0), 0.01, s));
  EXPECT_NEAR(s.gap, 0.002, kTolerance);
  expect_near(s.normal, Vec3::UnitY());
  ASSERT_TRUE(hopper().make_surface(false, {})->nearest(Vec3(0.0, 0.9, -0.1), 1.0, s));
  expect_near(s.point, Vec3(0.0, 1.0, 0.0));  // the open rim
  // A box and a cylinder as containers (open top) or solids.
  const Box box(Vec3::Zero(), Vec3::Ones());
  ASSERT_TRUE(box.make_surface(false, {Face{2, 1}})->nearest(Vec3(0.5, 0.5, 0.1), 0.2, s));
  EXPECT_NEAR(s.gap, 0.1, kTolerance);
  expect_near(s.normal, Vec3::UnitZ());
  EXPECT_FALSE(box.make_surface(false, {Face{2, 1}})->nearest(Vec3(0.5, 0.5, 0.9), 0.2, s));
  ASSERT_TRUE(box.make_surface(true, {})->nearest(Vec3(0.5, 0.5, 0.9), 0.2, s));
  EXPECT_NEAR(s.gap, -0.1, kTolerance);
  expect_near(s.normal, Vec3::UnitZ());
  const Cylinder cylinder(Vec3::Zero(), 1.0, 1.0);
  ASSERT_TRUE(cylinder.make_surface(false, {Face{2, 1}})->nearest(Vec3(0.0, 0.0, 0.1), 0.2, s));
  EXPECT_NEAR(s.gap, 0.1, kTolerance);
  expect_near(s.normal, Vec3::UnitZ());
  ASSERT_TRUE(cylinder.make_surface(true, {})->nearest(Vec3(0.0, 0.0, 1.1), 0.2, s));
  EXPECT_NEAR(s.gap, 0.1, kTolerance);
  expect_near(s.normal, Vec3::UnitZ());
}

TEST(Shapes, AMeshMakesATwoSidedShellOverItsTriangles) {
  // The unit cube, corners counter-clockwise seen from outside.
  const Vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  TriangleSoup soup;
  for (const auto& f : faces) {
    soup.push_back({{c[f[0]], c[f[1]], c[f[2]]}});
    soup.push_back({{c[f[0]], c[f[2]], c[f[3]]}});
  }
  const TriangleMesh cube(soup, Vec3(1.0, 0.0, 0.0));
  const auto shell = cube.make_surface(true, {});
  SurfacePoint s;
  ASSERT_TRUE(shell->nearest(Vec3(1.5, 0.5, 0.1), 0.2, s));  // inside, near the bottom
  EXPECT_NEAR(s.gap, 0.1, kTolerance);
  expect_near(s.normal, Vec3::UnitZ());
  ASSERT_TRUE(shell->nearest(Vec3(1.5, 0.5, -0.1), 0.2, s));  // outside, below it
  EXPECT_NEAR(s.gap, 0.1, kTolerance);
  expect_near(s.normal, -Vec3::UnitZ());
  EXPECT_FALSE(shell->nearest(Vec3(1.5, 0.5, 0.5), 0.2, s));
}

}  // namespace
}  // namespace partimix::geometry
