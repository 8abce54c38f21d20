// The temperatures conduction reads at a temperature boundary (sph/dirichlet_temperature.hpp):
// on a 2D lattice, a slab of held particles at T_b beside free ones at a uniform T_f, the held
// particles within reach of the free ones read 2 T_b - T_f (the kernel mean of a uniform field is
// that field), those beyond it T_b, and the free ones their own T.
#include <gtest/gtest.h>

#include <vector>

#include "particles/cell_grid.hpp"
#include "sph/dirichlet_temperature.hpp"
#include "sph/kernel.hpp"

namespace partimix::sph {
namespace {

TEST(DirichletTemperature, HeldParticlesMirrorTheirFreeNeighbours) {
  constexpr double kSpacing = 1.0;
  constexpr double kHeld = 301.0;
  constexpr double kFree = 300.2;
  std::vector<Vec3> position;
  std::vector<double> temperature;
  std::vector<std::uint8_t> held;
  for (int ix = 0; ix < 20; ++ix)
    for (int iy = 0; iy < 10; ++iy) {
      position.emplace_back(kSpacing * (ix + 0.5), kSpacing * (iy + 0.5), 0.0);
      held.push_back(ix < 10 ? 1 : 0);
      temperature.push_back(ix < 10 ? kHeld : kFree);
    }
  const std::size_t n = position.size();
  const std::vector<double> h(n, 1.5 * kSpacing);
  const auto kernel = kernel_registry().create("wendland_c2");
  const ScaledKernel scaled(*kernel, 2);
  Domain domain;
  domain.dimensions = 2;
  domain.hi = Vec3(20 * kSpacing, 10 * kSpacing, 0.0);
  domain.periodic = {false, true, false};
  CellGrid grid(domain, scaled.support() * h[0]);
  grid.build(position);
  std::vector<double> conducted(n);
  dirichlet_temperatures({position, h, temperature, held}, n, grid, scaled, conducted);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = position[i].x();
    if (held[i] == 0)
      EXPECT_EQ(conducted[i], kFree) << i;
    else if (10.5 * kSpacing - x < scaled.support() * h[i])  // the nearest free column, x = 10.5
      EXPECT_NEAR(conducted[i], 2.0 * kHeld - kFree, 1e-12) << i;
    else
      EXPECT_EQ(conducted[i], kHeld) << i;
  }
}

}  // namespace
}  // namespace partimix::sph
