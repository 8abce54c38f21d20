// The shape functions of the background grid (docs/mpm.md, "Shape functions"): at any point
// they sum to one and reproduce linear fields (so a uniform or linear velocity is mapped
// exactly), their gradients sum to zero and reproduce the identity, and the B-spline's gradient
// is continuous where a point crosses a cell face while the linear one's jumps.
#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"
#include "grid/cartesian_grid.hpp"
#include "grid/point_stencil.hpp"
#include "grid/shape_function.hpp"

namespace partimix::grid {
namespace {

Domain unit_domain(int dimensions) {
  Domain domain;
  domain.dimensions = dimensions;
  domain.lo = Vec3::Zero();
  domain.hi = dimensions == 3 ? Vec3(1.0, 0.5, 0.25) : Vec3(1.0, 0.5, 0.0);
  return domain;
}

class ShapeFunctions : public ::testing::TestWithParam<std::string> {};

TEST_P(ShapeFunctions, PartitionOfUnityAndLinearReproduction) {
  const auto shape = shape_function_registry().create(GetParam(), ShapeFunctionOptions{0.25});
  ASSERT_TRUE(shape);
  for (const int dimensions : {2, 3}) {
    const CartesianGrid grid(unit_domain(dimensions), 0.05, 1e7);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
      Vec3 x(u(random), 0.5 * u(random), dimensions == 3 ? 0.25 * u(random) : 0.0);
      double sum = 0.0;
      Vec3 first = Vec3::Zero();
      Vec3 gradient_sum = Vec3::Zero();
      Mat3 identity = Mat3::Zero();
      for_each_node(grid, point_stencil(*shape, grid, x), [&](std::size_t n, const NodeWeight& w) {
        sum += w.weight;
        first += w.weight * (grid.node_position(n) - x);
        gradient_sum += w.gradient;
        identity += grid.node_position(n) * w.gradient.transpose();
      });
      EXPECT_NEAR(sum, 1.0, 1e-12);
      EXPECT_LT(first.norm(), 1e-12);
      EXPECT_LT(gradient_sum.norm(), 1e-9);
      Mat3 expected = Mat3::Identity();
      if (dimensions == 2)
        expected(2, 2) = 0.0;
      EXPECT_LT((identity - expected).norm(), 1e-9) << GetParam() << " at " << x.transpose();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Grid, ShapeFunctions, ::testing::Values("linear", "gimp", "bspline"));

// Across a node (r = 0) and the B-spline's knots (r = 1/2, 3/2) the slope of the B-spline is
// continuous to the step; the linear slope jumps by 2 at r = 0.
TEST(ShapeFunctionsContinuity, BsplineSlopeIsContinuousLinearSlopeJumps) {
  const auto bspline = shape_function_registry().create("bspline", {});
  const auto linear = shape_function_registry().create("linear", {});
  const double e = 1e-9;
  for (const double knot : {0.0, 0.5, 1.5, -0.5, -1.5})
    EXPECT_NEAR(bspline->slope(knot - e), bspline->slope(knot + e), 1e-8) << knot;
  EXPECT_NEAR(linear->slope(-e) - linear->slope(e), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(bspline->value(0.0), 0.75);
  EXPECT_DOUBLE_EQ(bspline->value(1.0), 0.125);
}

// GIMP with a point half-width l equals the average of the linear function over the point's
// extent [r - l, r + l] (Bardenhagen & Kober 2004): checked by quadrature.
TEST(ShapeFunctionsGimp, IsTheLinearFunctionAveragedOverThePoint) {
  const double l = 0.25;
  const auto gimp = shape_function_registry().create("gimp", ShapeFunctionOptions{l});
  const auto linear = shape_function_registry().create("linear", {});
  for (double r = -1.4; r <= 1.4; r += 0.05) {
    const int samples = 20000;
    double mean = 0.0;
    for (int k = 0; k < samples; ++k)
      mean += linear->value(r - l + 2.0 * l * (k + 0.5) / samples);
    mean /= samples;
    EXPECT_NEAR(gimp->value(r), mean, 1e-6) << r;
  }
}

TEST(CartesianGrid, PeriodicLengthMustBeWholeCells) {
  Domain domain = unit_domain(2);
  domain.periodic[0] = true;
  EXPECT_EQ(CartesianGrid(domain, 0.05, 1e7).count(0), 20);
  EXPECT_THROW(CartesianGrid(domain, 0.03, 1e7), partimix::InputError);
  EXPECT_THROW(CartesianGrid(domain, 0.001, 1e4), partimix::InputError);
}

}  // namespace
}  // namespace partimix::grid
