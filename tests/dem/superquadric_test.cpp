// The superquadric shape of dem/superquadric.hpp (docs/dem.md, "Superquadric grains"): the
// volume and principal moments of a sphere and an ellipsoid against their closed forms (1e-12),
// of a blocky grain against a midpoint quadrature over its bounding box (0.3%), and the
// gradient and Hessian against central differences of the value (1e-6 relative), and the
// support point against the surface's farthest point along a direction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "dem/superquadric.hpp"

namespace partimix::dem {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Superquadric, EllipsoidVolumeAndInertiaHaveTheirClosedForms) {
  const Vec3 axes(1.0e-3, 2.0e-3, 3.0e-3);
  const Superquadric ellipsoid(axes, 2.0, 2.0);
  const double volume = 4.0 / 3.0 * kPi * axes.prod();
  EXPECT_NEAR(ellipsoid.volume(), volume, 1e-12 * volume);
  const Vec3 a2 = axes.cwiseProduct(axes);
  const Vec3 expected = volume / 5.0 * Vec3(a2.y() + a2.z(), a2.x() + a2.z(), a2.x() + a2.y());
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(ellipsoid.unit_inertia()[k], expected[k], 1e-12 * expected[k]);
  EXPECT_DOUBLE_EQ(ellipsoid.bounding_radius(), 3.0e-3);
  EXPECT_NEAR(ellipsoid.value(Vec3(0, 0, 3.0e-3)), 0.0, 1e-12);
  EXPECT_NEAR(ellipsoid.value(Vec3::Zero()), -1.0, 1e-15);
  // On the z axis the Hessian is diag(2/a^2, 2/b^2, 2/c^2) too.
  const Mat3 h = ellipsoid.hessian(Vec3(0, 0, 1.0e-3));
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(h(k, k), 2.0 / (axes[k] * axes[k]), 1e-9 / (axes[k] * axes[k]));
}

TEST(Superquadric, SphereIsTheEllipsoidWithEqualAxes) {
  const double r = 2.0e-3;
  const Superquadric sphere(Vec3::Constant(r), 2.0, 2.0);
  const double volume = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(sphere.volume(), volume, 1e-12 * volume);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(sphere.unit_inertia()[k], 0.4 * volume * r * r, 1e-12 * volume * r * r);
}

// Midpoint rule over the bounding box on a grid of n^3 cells: the volume and the moments.
TEST(Superquadric, BlockyVolumeAndInertiaMatchAQuadrature) {
  const Vec3 axes(1.0, 1.5, 2.0);
  const Superquadric grain(axes, 4.0, 6.0);
  const int n = 160;
  const Vec3 cell = 2.0 * axes / n;
  double volume = 0.0;
  Vec3 inertia = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Vec3 x = -axes + cell.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        if (grain.value(x) >= 0.0)
          continue;
        volume += 1.0;
        const Vec3 x2 = x.cwiseProduct(x);
        inertia += Vec3(x2.y() + x2.z(), x2.x() + x2.z(), x2.x() + x2.y());
      }
    }
  }
  const double dv = cell.prod();
  volume *= dv;
  inertia *= dv;
  RecordProperty("volume_error", std::to_string(grain.volume() / volume - 1.0));
  EXPECT_NEAR(grain.volume(), volume, 3e-3 * volume);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(grain.unit_inertia()[k], inertia[k], 3e-3 * inertia[k]);
}

TEST(Superquadric, GradientAndHessianMatchCentralDifferences) {
  const Superquadric grain(Vec3(1.0, 1.5, 2.0), 4.0, 6.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.2, 1.0);
  std::bernoulli_distribution flip(0.5);
  const double step = 1e-5;
  for (int sample = 0; sample < 200; ++sample) {
    Vec3 x(u(random), 1.5 * u(random), 2.0 * u(random));
    for (int k = 0; k < 3; ++k)
      x[k] = flip(random) ? -x[k] : x[k];
    const Vec3 g = grain.gradient(x);
    const Mat3 h = grain.hessian(x);
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = step * Vec3::Unit(k);
      const double dg = (grain.value(x + e) - grain.value(x - e)) / (2.0 * step);
      ASSERT_NEAR(g[k], dg, 1e-6 * (1.0 + std::abs(dg)));
      const Vec3 dh = (grain.gradient(x + e) - grain.gradient(x - e)) / (2.0 * step);
      for (int m = 0; m < 3; ++m)
        ASSERT_NEAR(h(m, k), dh[m], 1e-6 * (1.0 + h.cwiseAbs().maxCoeff()));
    }
  }
}

// The support point lies on the surface (|F| < 1e-12), its outward normal is along the
// direction (1e-9 rad), and no point of a dense sampling of the surface lies farther along it.
TEST(Superquadric, SupportPointIsTheFarthestAlongTheDirection) {
  std::mt19937 random(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const Vec3& shape : {Vec3(2, 2, 2), Vec3(2, 3, 2), Vec3(4, 6, 2), Vec3(10, 8, 3)}) {
    const Superquadric grain(Vec3(1.0, 1.5, 2.0), shape.x(), shape.y());
    for (int sample = 0; sample < 200; ++sample) {
      const Vec3 d = Vec3(normal(random), normal(random), normal(random)).normalized();
      const Vec3 x = grain.support(d);
      ASSERT_NEAR(grain.value(x), 0.0, 1e-12);
      const Vec3 g = grain.gradient(x).normalized();
      ASSERT_LT(g.cross(d).norm(), 1e-9);
      ASSERT_GT(g.dot(d), 0.0);
      // Surface points along random rays from the centre (bisection on F), none farther out.
      for (int ray = 0; ray < 50; ++ray) {
        const Vec3 e = Vec3(normal(random), normal(random), normal(random)).normalized();
        double inside = 0.0;
        double outside = 3.0;
        for (int halving = 0; halving < 60; ++halving) {
          const double middle = 0.5 * (inside + outside);
          (grain.value(middle * e) < 0.0 ? inside : outside) = middle;
        }
        ASSERT_LE(d.dot(inside * e), d.dot(x) + 1e-12);
      }
    }
    EXPECT_NEAR(grain.support(Vec3(0, 0, -5)).z(), -2.0, 1e-15);
    EXPECT_NEAR(grain.support(Vec3(3, 0, 0)).x(), 1.0, 1e-12);
  }
}

TEST(Superquadric, RejectsBadShapes) {
  EXPECT_THROW(Superquadric(Vec3(1, 0, 1), 2, 2), std::invalid_argument);
  EXPECT_THROW(Superquadric(Vec3(1, 1, 1), 1.5, 2), std::invalid_argument);
}

}  // namespace
}  // namespace partimix::dem
