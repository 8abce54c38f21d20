// Density diffusion on a fluid at rest with the hydrostatic density rho0 + rho0 |g| (H - y) / c0^2.
// The Fourtakas et al. (2019) term vanishes everywhere, the free surface included, because it
// subtracts the hydrostatic part pair by pair ("vanishes": below 1e-9 of the term of one nearest
// pair with a one-layer density step, i.e. round-off). The Molteni and Colagrossi (2009) term
// nearly vanishes where the kernel is full (odd pairs cancel on a symmetric lattice) but diffuses
// the gradient where the kernel is cut, raising the density of the top layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "particles/neighbour_list.hpp"
#include "sph/fluid_rates.hpp"
#include "sph/kernel.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 0.01;
constexpr int kSide = 20;
constexpr double kHeight = kSide * kSpacing;

struct HydrostaticBlock {
  ParticleStore store;
  Fields fields{store};
  Parameters parameters;
  Domain domain;

  explicit HydrostaticBlock(DensityDiffusion diffusion) {
    domain.dimensions = 2;
    domain.lo = Vec3(-1.0, -1.0, 0.0);
    domain.hi = Vec3(1.0, 1.0, 0.0);
    parameters.dimensions = 2;
    parameters.spacing = kSpacing;
    parameters.h = 1.5 * kSpacing;
    parameters.eta2 = 0.01 * parameters.h * parameters.h;
    parameters.reference_density = 1000.0;
    parameters.sound_speed = 20.0;
    parameters.gravity = Vec3(0.0, -9.81, 0.0);
    parameters.hydrostatic_gravity = parameters.gravity;
    parameters.viscous_operator = ViscousOperator::none;
    parameters.diffusion = diffusion;
    store.resize(kSide * kSide);
    for (int j = 0; j < kSide; ++j) {
      for (int i = 0; i < kSide; ++i) {
        const auto k = static_cast<std::size_t>(j * kSide + i);
        const Vec3 x((i + 0.5) * kSpacing, (j + 0.5) * kSpacing, 0.0);
        fields.position[k] = x;
        fields.mass[k] = 1000.0 * kSpacing * kSpacing;
        fields.density[k] = 1000.0 * (1.0 + 9.81 * (kHeight - x.y()) / (20.0 * 20.0));
      }
    }
  }

  // Density rates of all particles (velocities and pressures zero: diffusion only).
  const std::vector<double>& density_rates() {
    const auto kernel = kernel_registry().create("wendland_c2");
    const KernelTable table(*kernel, parameters.h, 2);
    NeighbourList list(domain, table.support_radius(), 0.1 * table.support_radius());
    list.update(fields.position, store.size(), store.size());
    RateBuffers buffers;
    compute_fluid_rates(fields, store.size(), list, table, parameters, buffers);
    return fields.density_rate;
  }
};

// One nearest-neighbour pair's Molteni term for the density step of one layer,
// 2 delta h c0 drho (-dW/dr / r) V at r = dp: the scale the rates are compared with.
double pair_scale() {
  const auto kernel = kernel_registry().create("wendland_c2");
  const double slope = -kernel_derivative(*kernel, kSpacing, 1.5 * kSpacing, 2) / kSpacing;
  const double step = 1000.0 * 9.81 * kSpacing / (20.0 * 20.0);
  return 2.0 * 0.1 * 1.5 * kSpacing * 20.0 * step * slope * kSpacing * kSpacing;
}

TEST(DensityDiffusion, FourtakasVanishesOnTheHydrostaticState) {
  HydrostaticBlock block(DensityDiffusion::fourtakas);
  for (double rate : block.density_rates()) {
    EXPECT_NEAR(rate, 0.0, 1e-9 * pair_scale());
  }
}

// Inside, only the second-order term from V_j = m / rho_j varying with depth is left.
TEST(DensityDiffusion, MolteniIsSmallInsideButDiffusesAtTheFreeSurface) {
  HydrostaticBlock block(DensityDiffusion::molteni);
  const auto& rates = block.density_rates();
  double top = std::numeric_limits<double>::max();
  double inside = 0.0;
  for (std::size_t k = 0; k < rates.size(); ++k) {
    const Vec3& x = block.fields.position[k];
    const bool away_from_sides = x.x() > 0.04 && x.x() < kHeight - 0.04;
    if (away_from_sides && x.y() > kHeight - kSpacing)
      top = std::min(top, rates[k]);
    if (away_from_sides && x.y() > 0.04 && x.y() < kHeight - 0.04) {
      inside = std::max(inside, std::abs(rates[k]));
    }
  }
  std::printf("Molteni: top layer %.4g, inside %.4g, pair scale %.4g\n", top, inside, pair_scale());
  EXPECT_GT(top, 0.1 * pair_scale());
  EXPECT_LT(inside, 0.01 * top);
}

}  // namespace
}  // namespace partimix::sph
