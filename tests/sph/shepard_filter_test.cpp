// Shepard filter (seed eq. 20): a uniform density is kept exactly, also where the kernel is cut
// by a free surface, and a noisy density is smoothed towards its local mean.
#include <gtest/gtest.h>

#include <random>

#include "particles/cell_grid.hpp"
#include "sph/kernel.hpp"
#include "sph/kernel_table.hpp"
#include "sph/shepard_filter.hpp"

namespace partimix::sph {
namespace {

struct Block {
  ParticleStore store;
  Domain domain;
};

void fill_block(Block& b, double dp, int n) {
  b.domain.dimensions = 2;
  b.domain.lo = Vec3(-1.0, -1.0, 0.0);
  b.domain.hi = Vec3(1.0, 1.0, 0.0);
  b.store.resize(static_cast<std::size_t>(n * n));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(j * n + i);
      b.store.position()[k] = Vec3((i + 0.5) * dp, (j + 0.5) * dp, 0.0);
      b.store.mass()[k] = 1000.0 * dp * dp;
    }
  }
}

void filter(Fields& fields, const Domain& domain, double dp) {
  const auto kernel = kernel_registry().create("wendland_c2");
  const KernelTable table(*kernel, 1.5 * dp, 2);
  CellGrid grid(domain, table.support_radius());
  grid.build(fields.position);
  std::vector<double> scratch;
  apply_shepard_filter(fields, grid, table, scratch);
}

TEST(ShepardFilter, KeepsAUniformDensityExactlyUpToTheFreeSurface) {
  Block b;
  const double dp = 0.01;
  fill_block(b, dp, 20);
  Fields fields(b.store);
  std::fill(fields.density.begin(), fields.density.end(), 1000.0);
  filter(fields, b.domain, dp);
  for (double rho : fields.density)
    EXPECT_NEAR(rho, 1000.0, 1e-9);
}

TEST(ShepardFilter, SmoothsNoiseTowardsTheMean) {
  Block b;
  const double dp = 0.01;
  fill_block(b, dp, 30);
  Fields fields(b.store);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 5.0);
  for (double& rho : fields.density)
    rho = 1000.0 + noise(rng);
  auto spread = [&] {
    double s = 0.0;
    for (double rho : fields.density)
      s += (rho - 1000.0) * (rho - 1000.0);
    return std::sqrt(s / static_cast<double>(fields.density.size()));
  };
  const double before = spread();
  filter(fields, b.domain, dp);
  // Averaging over about 28 neighbours with weights W: the spread falls several times.
  EXPECT_LT(spread(), 0.4 * before);
}

}  // namespace
}  // namespace partimix::sph
