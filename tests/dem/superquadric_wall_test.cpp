// A superquadric grain against a wall (docs/dem.md, "Walls and superquadrics"): a turned
// ellipsoid on a plane against the ellipsoid's support function in closed form (1e-12); a
// sphere-shaped grain in a drum against the sphere's overlap R - gap (1e-12); a turned ellipsoid
// in a drum and a blocky grain on a plane against the deepest of 40,000 surface points
// (overlap within 2e-3 of the smallest half-axis, normal within 1e-9 rad of the wall's).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "dem/superquadric_wall.hpp"
#include "geometry/drum_surface.hpp"
#include "geometry/plane_surface.hpp"

namespace partimix::dem {
namespace {

Mat3 turned(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(SuperquadricWall, TurnedEllipsoidOnAPlaneMatchesItsSupportFunction) {
  const Vec3 axes(1.0e-3, 2.0e-3, 3.0e-3);
  const Superquadric grain(axes, 2.0, 2.0);
  const geometry::PlaneSurface floor(Vec3::Zero(), Vec3::UnitY());
  const Mat3 q = turned(0.7, Vec3(1, 2, 3));
  const Mat3 shape = q * axes.cwiseProduct(axes).asDiagonal() * q.transpose();
  const double height = std::sqrt(Vec3::UnitY().dot(shape * Vec3::UnitY()));
  const Vec3 centre(0.01, height - 2.0e-4, -0.02);
  const WallContact contact = superquadric_wall_contact(grain, centre, q, floor);
  ASSERT_TRUE(contact.touching);
  EXPECT_TRUE(contact.converged);
  EXPECT_NEAR(contact.overlap, 2.0e-4, 1e-15);
  EXPECT_LT((contact.normal - Vec3::UnitY()).norm(), 1e-15);
  const Vec3 deepest = centre - shape * Vec3::UnitY() / height;
  EXPECT_LT((contact.point - (deepest + 1.0e-4 * Vec3::UnitY())).norm(), 1e-15);
  EXPECT_FALSE(
      superquadric_wall_contact(grain, centre + 3.0e-4 * Vec3::UnitY(), q, floor).touching);
}

TEST(SuperquadricWall, SphereShapedGrainInADrumOverlapsAsTheSphere) {
  const double r = 2.0e-3;
  const Superquadric grain(Vec3::Constant(r), 2.0, 2.0);
  const geometry::DrumSurface drum(Vec3::Zero(), Vec3::UnitZ(), 0.1);
  const Vec3 centre = (0.1 - r + 3.0e-4) * Vec3(0.6, -0.8, 0.0) + Vec3(0, 0, 0.01);
  const WallContact contact =
      superquadric_wall_contact(grain, centre, turned(1.0, Vec3(1, 1, 0)), drum);
  ASSERT_TRUE(contact.touching);
  EXPECT_NEAR(contact.overlap, 3.0e-4, 1e-12);
  EXPECT_LT((contact.normal - Vec3(-0.6, 0.8, 0.0)).norm(), 1e-12);
}

// The deepest of many surface points (along rays from the centre, by bisection on F) into the
// wall: the largest -gap.
double deepest_sampled(const Superquadric& grain, const Vec3& centre, const Mat3& q,
                       const geometry::Surface& wall) {
  std::mt19937 random(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  double deepest = -1.0;
  for (int ray = 0; ray < 40000; ++ray) {
    const Vec3 e = Vec3(normal(random), normal(random), normal(random)).normalized();
    double inside = 0.0;
    double outside = 2.0 * grain.bounding_radius();
    for (int halving = 0; halving < 50; ++halving) {
      const double middle = 0.5 * (inside + outside);
      (grain.value(middle * e) < 0.0 ? inside : outside) = middle;
    }
    geometry::SurfacePoint at;
    if (wall.nearest(centre + q * (inside * e), 1.0, at))
      deepest = std::max(deepest, -at.gap);
  }
  return deepest;
}

TEST(SuperquadricWall, TurnedEllipsoidInADrumAndBlockyGrainOnAPlaneMatchSampledSurfaces) {
  const geometry::DrumSurface drum(Vec3::Zero(), Vec3::UnitZ(), 0.02);
  const Superquadric ellipsoid(Vec3(1.0e-3, 1.0e-3, 3.0e-3), 2.0, 2.0);
  const Mat3 q = turned(0.9, Vec3(1, -2, 0.5));
  const Vec3 centre(0.0, -0.0186, 0.0);
  const WallContact in_drum = superquadric_wall_contact(ellipsoid, centre, q, drum);
  ASSERT_TRUE(in_drum.touching);
  EXPECT_TRUE(in_drum.converged);
  EXPECT_NEAR(in_drum.overlap, deepest_sampled(ellipsoid, centre, q, drum), 2e-6);

  const geometry::PlaneSurface floor(Vec3::Zero(), Vec3(0.2, 1.0, 0.1));
  const Superquadric blocky(Vec3(1.0e-3, 1.5e-3, 2.0e-3), 6.0, 4.0);
  const Mat3 tilt = turned(0.4, Vec3(2, 1, -1));
  const Vec3 up = Vec3(0.2, 1.0, 0.1).normalized();
  const Vec3 above = 1.5e-3 * up;
  const WallContact on_floor = superquadric_wall_contact(blocky, above, tilt, floor);
  ASSERT_TRUE(on_floor.touching);
  EXPECT_NEAR(on_floor.overlap, deepest_sampled(blocky, above, tilt, floor), 2e-6);
  EXPECT_LT((on_floor.normal - up).norm(), 1e-9);
}

}  // namespace
}  // namespace partimix::dem
