// Kernels: normalisation (integral of W is one in 2D and 3D), gradient consistency
// (-int r (x) grad W dV = I, the condition that makes the SPH gradient exact for linear fields),
// slope against finite differences, and the hot-loop table against the analytic kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/vec.hpp"
#include "sph/kernel.hpp"
#include "sph/kernel_table.hpp"

namespace partimix::sph {
namespace {

// Midpoint-rule integrals over a lattice of spacing h / steps covering the support.
struct Moments {
  double integral = 0.0;
  Mat3 gradient_moment = Mat3::Zero();  // -sum x (x) grad W dV
  Vec3 gradient_sum = Vec3::Zero();     // sum grad W dV
};

Moments integrate(const Kernel& kernel, int dimensions, double h, int steps) {
  const double d = h / steps;
  const double reach = kernel.support() * h;
  const int n = static_cast<int>(std::ceil(reach / d));
  const int nz = dimensions == 3 ? n : 0;
  const double volume = std::pow(d, dimensions);
  Moments m;
  for (int k = -nz; k <= nz - (dimensions == 3 ? 1 : 0); ++k) {
    for (int j = -n; j < n; ++j) {
      for (int i = -n; i < n; ++i) {
        const Vec3 x((i + 0.5) * d, (j + 0.5) * d, dimensions == 3 ? (k + 0.5) * d : 0.0);
        const double r = x.norm();
        m.integral += kernel_value(kernel, r, h, dimensions) * volume;
        const Vec3 grad = kernel_derivative(kernel, r, h, dimensions) / r * x;
        m.gradient_sum += grad * volume;
        m.gradient_moment -= x * grad.transpose() * volume;
      }
    }
  }
  return m;
}

class KernelTest : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Kernel> kernel = kernel_registry().create(GetParam());
};

TEST_P(KernelTest, IsRegistered) {
  ASSERT_NE(kernel, nullptr);
}

// The midpoint rule at h/40 (2D) and h/20 (3D) integrates these piecewise polynomials to
// about 1e-5; 1e-4 leaves room for the kinks of the cubic spline and hyperbolic kernels.
TEST_P(KernelTest, NormalisedIn2D) {
  const Moments m = integrate(*kernel, 2, 0.7, 40);
  EXPECT_NEAR(m.integral, 1.0, 1e-4);
}

TEST_P(KernelTest, NormalisedIn3D) {
  const Moments m = integrate(*kernel, 3, 0.7, 20);
  EXPECT_NEAR(m.integral, 1.0, 1e-4);
}

TEST_P(KernelTest, GradientIsConsistentIn2D) {
  const Moments m = integrate(*kernel, 2, 0.7, 40);
  EXPECT_LT((m.gradient_moment.topLeftCorner<2, 2>() - Eigen::Matrix2d::Identity()).norm(), 1e-3);
  EXPECT_LT(m.gradient_sum.norm(), 1e-9);
}

TEST_P(KernelTest, GradientIsConsistentIn3D) {
  const Moments m = integrate(*kernel, 3, 0.7, 20);
  EXPECT_LT((m.gradient_moment - Mat3::Identity()).norm(), 2e-3);
  EXPECT_LT(m.gradient_sum.norm(), 1e-9);
}

TEST_P(KernelTest, SlopeMatchesFiniteDifference) {
  const double e = 1e-6;
  for (double q = 0.05; q < kernel->support(); q += 0.1) {
    const double numeric = (kernel->shape(q + e) - kernel->shape(q - e)) / (2.0 * e);
    EXPECT_NEAR(kernel->shape_derivative(q), numeric, 1e-6) << "q = " << q;
  }
}

TEST_P(KernelTest, VanishesAtSupport) {
  EXPECT_NEAR(kernel->shape(kernel->support()), 0.0, 1e-12);
  EXPECT_NEAR(kernel->shape_derivative(kernel->support()), 0.0, 1e-12);
}

// Linear interpolation on 4096 intervals: error <= (dq)^2 / 8 max|f''| ~ 1e-7 of the peak.
TEST_P(KernelTest, TableMatchesAnalyticKernel) {
  const double h = 0.013;
  for (int dimensions : {2, 3}) {
    const KernelTable table(*kernel, h, dimensions);
    const double peak = kernel_value(*kernel, 0.0, h, dimensions);
    const double peak_slope = std::abs(kernel_derivative(*kernel, 0.9 * h, h, dimensions));
    for (double r = 0.0; r < table.support_radius(); r += 0.00137 * h) {
      EXPECT_NEAR(table.value(r), kernel_value(*kernel, r, h, dimensions), 1e-6 * peak);
      EXPECT_NEAR(table.derivative(r), kernel_derivative(*kernel, r, h, dimensions),
                  1e-5 * peak_slope);
    }
    EXPECT_EQ(table.value(table.support_radius() * 1.01), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(AllKernels, KernelTest,
                         ::testing::Values("cubic_spline", "wendland_c2", "hyperbolic"));

}  // namespace
}  // namespace partimix::sph
