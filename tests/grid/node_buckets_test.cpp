// The gather of grid/node_buckets.hpp visits, for every node, exactly the points whose stencils
// cover it with the same weights a scatter would use: the gathered nodal masses equal the
// scattered ones, also across periodic faces, and every covered node is active.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "grid/node_buckets.hpp"

namespace partimix::grid {
namespace {

TEST(NodeBuckets, GatherEqualsScatterAcrossPeriodicFaces) {
  Domain domain;
  domain.dimensions = 3;
  domain.hi = Vec3(0.4, 0.3, 0.2);
  domain.periodic = {true, false, true};
  const CartesianGrid grid(domain, 0.05, 1e7);
  const auto shape = shape_function_registry().create("bspline", {});
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<PointStencil> stencils;
  std::vector<double> mass;
  for (int p = 0; p < 500; ++p) {
    stencils.push_back(
        point_stencil(*shape, grid, Vec3(0.4 * u(random), 0.3 * u(random), 0.2 * u(random))));
    mass.push_back(1.0 + u(random));
  }
  std::map<std::size_t, double> scattered;
  for (std::size_t p = 0; p < stencils.size(); ++p) {
    for_each_node(grid, stencils[p],
                  [&](std::size_t n, const NodeWeight& w) { scattered[n] += w.weight * mass[p]; });
  }
  NodeBuckets buckets;
  buckets.build(grid, stencils);
  ASSERT_EQ(buckets.active_nodes().size(), scattered.size());
  for (const std::size_t n : buckets.active_nodes()) {
    double gathered = 0.0;
    buckets.for_each_point(grid, n, [&](std::uint32_t p, int a, int b, int c) {
      gathered += node_weight(stencils[p], a, b, c, grid.cell_size()).weight * mass[p];
    });
    ASSERT_TRUE(scattered.contains(n));
    EXPECT_NEAR(gathered, scattered[n], 1e-12 * scattered[n]);
  }
}

}  // namespace
}  // namespace partimix::grid
