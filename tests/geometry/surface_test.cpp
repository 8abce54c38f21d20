// The nearest point, normal and gap of the plane, drum, cone and mesh contact surfaces
// (docs/dem.md, "Walls"), against points whose answer is known by construction, to 1e-12.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/cone_surface.hpp"
#include "geometry/drum_surface.hpp"
#include "geometry/mesh_shell_surface.hpp"
#include "geometry/plane_surface.hpp"

namespace partimix::geometry {
namespace {

constexpr double kTolerance = 1e-12;

void expect_near(const Vec3& a, const Vec3& b) {
  EXPECT_LT((a - b).norm(), kTolerance) << a.transpose() << " vs " << b.transpose();
}

TEST(Surface, PlaneGapIsTheSignedDistanceOnTheNormalSide) {
  const PlaneSurface plane(Vec3(0.0, 1.0, 0.0), Vec3(0.0, 2.0, 0.0));
  SurfacePoint s;
  ASSERT_TRUE(plane.nearest(Vec3(3.0, 1.5, -2.0), 1.0, s));
  EXPECT_NEAR(s.gap, 0.5, kTolerance);
  expect_near(s.point, Vec3(3.0, 1.0, -2.0));
  expect_near(s.normal, Vec3::UnitY());
  EXPECT_FALSE(plane.nearest(Vec3(0.0, 2.5, 0.0), 1.0, s));
}

TEST(Surface, DrumNormalPointsToTheAxis) {
  const DrumSurface drum(Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 5.0), 0.1);
  SurfacePoint s;
  ASSERT_TRUE(drum.nearest(Vec3(1.0, -0.098, 7.0), 0.01, s));
  EXPECT_NEAR(s.gap, 0.002, kTolerance);
  expect_near(s.point, Vec3(1.0, -0.1, 7.0));
  expect_near(s.normal, Vec3::UnitY());
  EXPECT_FALSE(drum.nearest(Vec3(1.0, 0.0, 0.0), 0.01, s));
}

TEST(Surface, ConeNearestPointOnTheGeneratorAndOnTheRim) {
  // Radius 1 at z = 0 growing to 2 at z = 1: the generator makes 45 degrees with the axis.
  const ConeSurface cone(Vec3::Zero(), Vec3::UnitZ(), 1.0, 2.0, 1.0);
  SurfacePoint s;
  ASSERT_TRUE(cone.nearest(Vec3(1.0, 0.0, 0.5), 1.0, s));
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(s.gap, 0.5 * h, kTolerance);
  expect_near(s.point, Vec3(1.25, 0.0, 0.25));
  expect_near(s.normal, Vec3(-h, 0.0, h));
  ASSERT_TRUE(cone.nearest(Vec3(0.0, 0.9, -0.1), 1.0, s));  // below the small rim
  expect_near(s.point, Vec3(0.0, 1.0, 0.0));
  EXPECT_NEAR(s.gap, std::sqrt(0.02), kTolerance);
}

TEST(Surface, MeshIsTwoSidedAndTakesTheNearestFeature) {
  TriangleSoup square{{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}},
                      {{Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}}};
  const MeshShellSurface mesh(square);
  SurfacePoint s;
  ASSERT_TRUE(mesh.nearest(Vec3(0.3, 0.6, -0.2), 0.5, s));
  EXPECT_NEAR(s.gap, 0.2, kTolerance);
  expect_near(s.normal, -Vec3::UnitZ());
  ASSERT_TRUE(mesh.nearest(Vec3(1.3, 0.5, 0.4), 0.6, s));  // beyond the edge x = 1
  expect_near(s.point, Vec3(1.0, 0.5, 0.0));
  EXPECT_NEAR(s.gap, 0.5, kTolerance);
  EXPECT_FALSE(mesh.nearest(Vec3(0.5, 0.5, 2.0), 0.5, s));
}

}  // namespace
}  // namespace partimix::geometry
