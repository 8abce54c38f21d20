// The gauge of dem/superquadric_gauge.hpp: N - 1 with N = (F + 1)^(1/n1) from
// Superquadric::value (1e-12), N homogeneous (1e-11) of degree 1, and its gradient and Hessian
// against central differences (1e-6 relative), on ellipsoids and blocky grains, including points on
// the body axes and planes where the powers' limits are taken.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dem/superquadric.hpp"
#include "dem/superquadric_gauge.hpp"

namespace partimix::dem {
namespace {

TEST(SuperquadricGauge, IsTheRootOfTheShapeFunctionAndHomogeneous) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const auto& [n1, n2] : {std::pair{2.0, 2.0}, {3.0, 2.0}, {2.0, 5.5}, {10.0, 8.0}}) {
    const Superquadric grain(Vec3(1.0, 1.5, 0.7), n1, n2);
    for (int k = 0; k < 100; ++k) {
      const Vec3 x(u(random), u(random), u(random));
      const double n = std::pow(grain.value(x) + 1.0, 1.0 / n1);
      EXPECT_NEAR(gauge(grain, x), n - 1.0, 1e-12 * n);
      EXPECT_NEAR(gauge_local(grain, x).value, n - 1.0, 1e-12 * n);
      EXPECT_NEAR(gauge(grain, 2.5 * x) + 1.0, 2.5 * n, 1e-11 * n);
    }
  }
}

TEST(SuperquadricGauge, DerivativesMatchCentralDifferences) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const double step = 1e-6;
  for (const auto& [n1, n2] : {std::pair{2.0, 2.0}, {4.0, 6.0}, {10.0, 3.0}, {2.0, 8.0}}) {
    const Superquadric grain(Vec3(1.0, 1.5, 0.7), n1, n2);
    for (int sample = 0; sample < 100; ++sample) {
      Vec3 x(u(random), u(random), u(random));
      // Some points on the body planes and on the z axis.
      if (sample % 10 == 0)
        x.x() = 0.0;
      if (sample % 20 == 0)
        x.y() = 0.0;
      const GaugeLocal g = gauge_local(grain, x);
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = step * Vec3::Unit(k);
        const double dg = (gauge(grain, x + e) - gauge(grain, x - e)) / (2.0 * step);
        ASSERT_NEAR(g.gradient[k], dg, 1e-6 * (1.0 + std::abs(dg)));
        const Vec3 dh =
            (gauge_local(grain, x + e).gradient - gauge_local(grain, x - e).gradient) / (2 * step);
        for (int m = 0; m < 3; ++m)
          ASSERT_NEAR(g.hessian(m, k), dh[m], 1e-5 * (1.0 + g.hessian.cwiseAbs().maxCoeff()))
              << n1 << " " << n2 << " " << x.transpose();
      }
    }
  }
}

}  // namespace
}  // namespace partimix::dem
