// The averaged dilation of mpm/transfers.hpp (docs/mpm.md, "Dilation: local or averaged"): it keeps
// a uniform rate and the deviatoric part of every L_p exactly, keeps the mass-weighted sum of the
// points' dilation rates to round-off, and removes a point-to-point checkerboard in tr L (the
// noise that loosened draining bins) exactly where the points' masses are equal.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "grid/node_buckets.hpp"
#include "mpm/transfers.hpp"

namespace partimix::mpm {
namespace {

constexpr double kCell = 0.01;
constexpr int kPointsPerAxis = 20;  // 2 x 2 points per cell over 10 x 10 cells

struct Block {
  grid::CartesianGrid grid;
  std::vector<grid::PointStencil> stencils;
  std::vector<double> mass;
  std::vector<int> parity;  // +1 / -1 in a checkerboard over the point lattice
  grid::NodeBuckets buckets;
  GridFields nodes;
};

Domain square_domain() {
  Domain domain;
  domain.dimensions = 2;
  domain.lo = Vec3(-0.05, -0.05, 0);
  domain.hi = Vec3(0.15, 0.15, 0);
  return domain;
}

// Uneven point masses unless `equal_masses`.
Block make_block(bool equal_masses = false) {
  Block block{grid::CartesianGrid(square_domain(), kCell, 1e7), {}, {}, {}, {}, {}};
  const auto shape = grid::shape_function_registry().create("bspline", {});
  for (int i = 0; i < kPointsPerAxis; ++i) {
    for (int j = 0; j < kPointsPerAxis; ++j) {
      const Vec3 x((i + 0.5) * kCell / 2, (j + 0.5) * kCell / 2, 0.0);
      block.stencils.push_back(grid::point_stencil(*shape, block.grid, x));
      block.mass.push_back(equal_masses ? 1.0 : 1.0 + 0.1 * ((i * 7 + j * 3) % 5));
      block.parity.push_back((i + j) % 2 == 0 ? 1 : -1);
    }
  }
  block.buckets.build(block.grid, block.stencils);
  block.nodes.resize(block.grid.node_count());
  for (const std::size_t n : block.buckets.active_nodes()) {
    double m = 0.0;
    block.buckets.for_each_point(block.grid, n, [&](std::uint32_t p, int a, int b, int c) {
      m += grid::node_weight(block.stencils[p], a, b, c, kCell).weight * block.mass[p];
    });
    block.nodes.mass[n] = m;
  }
  return block;
}

// L_p: a uniform dilation rate, a shear, and a checkerboard of +-noise on the diagonal.
std::vector<Mat3> gradients(const Block& block, double rate, double noise) {
  std::vector<Mat3> l(block.stencils.size());
  for (std::size_t p = 0; p < l.size(); ++p) {
    l[p] = Mat3::Zero();
    l[p](0, 0) = rate / 2 + noise * block.parity[p];
    l[p](1, 1) = rate / 2 + noise * block.parity[p];
    l[p](0, 1) = 3.0;
    l[p](1, 0) = -1.0;
  }
  return l;
}

void average(Block& block, std::vector<Mat3>& l) {
  average_dilation(block.grid, block.buckets, block.stencils, block.mass, 0.0, block.nodes, l);
}

TEST(AverageDilation, KeepsAUniformRateAndTheDeviatoricPart) {
  Block block = make_block();
  std::vector<Mat3> l = gradients(block, 2.0, 0.0);
  const std::vector<Mat3> before = l;
  average(block, l);
  for (std::size_t p = 0; p < l.size(); ++p)
    ASSERT_LT((l[p] - before[p]).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(AverageDilation, KeepsTheMassWeightedSumOfTheRates) {
  Block block = make_block();
  std::vector<Mat3> l = gradients(block, 2.0, 0.7);
  for (std::size_t p = 0; p < l.size(); ++p)
    l[p](0, 0) += 0.01 * static_cast<double>(p % 13);
  double before = 0.0;
  for (std::size_t p = 0; p < l.size(); ++p)
    before += block.mass[p] * l[p].trace();
  average(block, l);
  double after = 0.0;
  for (std::size_t p = 0; p < l.size(); ++p) {
    after += block.mass[p] * l[p].trace();
    ASSERT_EQ(l[p](0, 1), 3.0);
    ASSERT_EQ(l[p](1, 0), -1.0);
  }
  EXPECT_NEAR(after, before, 1e-12 * std::abs(before));
}

// A checkerboard of equal-mass points, two per cell along each axis, vanishes exactly at every
// node whose stencil sees a whole symmetric neighbourhood: the points at +d and -d from a node
// carry the same B-spline weight and opposite signs, along each axis, and the 2D weight and sign
// factorise. So three cells in from the block's edges tr L is the uniform rate to round-off.
// (With uneven masses the cancellation is partial: 6.2% of the amplitude is left for the masses
// of make_block(), recorded, not asserted.)
TEST(AverageDilation, RemovesAPointToPointCheckerboard) {
  const double noise = 0.5;
  const auto remaining = [&](bool equal_masses) {
    Block block = make_block(equal_masses);
    std::vector<Mat3> l = gradients(block, 2.0, noise);
    average(block, l);
    double worst = 0.0;
    for (int i = 6; i < kPointsPerAxis - 6; ++i) {
      for (int j = 6; j < kPointsPerAxis - 6; ++j)
        worst = std::max(worst, std::abs(l[i * kPointsPerAxis + j].trace() - 2.0));
    }
    return worst / (2 * noise);
  };
  EXPECT_LT(remaining(true), 1e-12);
  RecordProperty("remaining_fraction_uneven_masses", std::to_string(remaining(false)));
}

}  // namespace
}  // namespace partimix::mpm
