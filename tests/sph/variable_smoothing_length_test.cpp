// The weakly-compressible scheme's variable smoothing length (docs/sph.md, "Variable smoothing
// length"): the pair's kernel gradient read from the reference h's table against the kernel
// evaluated directly at h_i and h_j; each particle's h_i = eta (m_i / rho_i)^(1/d) in the solver's
// output field, the search widening for one that outgrows it; and a particle whose h would
// grow beyond 4 h stops the run. The
// pair sums themselves are checked term by term in fluid_rates_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "sph/kernel.hpp"
#include "sph/pair_rates.hpp"
#include "sph/sph_solver.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 0.01;
constexpr double kDensity = 1000.0;

// Scales within 20% of 1 and distances across the larger support: the table's mean gradient
// within 1e-5 of the largest (its interpolation error, docs/sph.md "Kernels"), the same both
// ways round.
TEST(VariableSmoothingLength, PairGradientIsTheMeanOfBothKernels) {
  const auto kernel = kernel_registry().create("wendland_c2");
  Parameters p;
  p.h = 1.5 * kSpacing;
  const KernelTable table(*kernel, p.h, 3);
  ParticleStore store;
  store.resize(2);
  Fields f(store);
  const double scales[] = {0.8, 1.2};
  f.kernel_scale.assign(scales, scales + 2);
  f.gradient_scale = {std::pow(0.8, 4), std::pow(1.2, 4)};
  const PairCentre first = pair_centre(0, f, p);
  const PairCentre second = pair_centre(1, f, p);
  EXPECT_DOUBLE_EQ(first.h, p.h / 0.8);
  const double largest = std::abs(kernel_derivative(*kernel, 0.5 * p.h, p.h / 1.2, 3));
  for (double r = 0.05 * p.h; r < 2.0 * p.h / 0.8; r += 0.05 * p.h) {
    const double expected = 0.5 * (kernel_derivative(*kernel, r, p.h / 0.8, 3) +
                                   kernel_derivative(*kernel, r, p.h / 1.2, 3));
    const PairKernel ij = pair_kernel(first, 1, r, f, table, p);
    const PairKernel ji = pair_kernel(second, 0, r, f, table, p);
    EXPECT_NEAR(ij.gradient_factor * r, expected, 1e-5 * largest) << r;
    EXPECT_EQ(ij.gradient_factor, ji.gradient_factor) << r;
    EXPECT_DOUBLE_EQ(ij.h, 0.5 * (p.h / 0.8 + p.h / 1.2));
    EXPECT_NEAR(centre_gradient_factor(first, r, table) * r,
                kernel_derivative(*kernel, r, p.h / 0.8, 3), 1e-5 * largest)
        << r;
  }
}

struct Box {
  ParticleStore store;
  Domain domain;
  Config config;
  FluidProperties fluid;

  Box() {
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j) {
        const std::size_t n = store.size();
        store.resize(n + 1);
        store.position()[n] = kSpacing * Vec3(i + 0.5, j + 0.5, 0.0);
        store.kind()[n] = static_cast<std::int32_t>(ParticleKind::fluid);
        store.id()[n] = static_cast<std::int64_t>(n);
      }
    domain.dimensions = 2;
    domain.hi = Vec3(20 * kSpacing, 20 * kSpacing, 0.0);
    domain.periodic = {true, true, false};
    config.spacing = kSpacing;
    config.sound_speed = 10.0;
    config.variable_smoothing_length = true;
    fluid.density = kDensity;
  }
};

// Densities 0.9 to 1.1 rho0 (by particle index), one at 0.6 rho0 (h_i = 1.29 h, beyond the
// search's first 1.05 h): after a step of 1e-9 s every h_i is 1.5 dp (m / rho_i)^(1/2) to
// round-off.
TEST(VariableSmoothingLength, EachParticlesHFollowsItsDensity) {
  Box box;
  SphSolver solver(box.store, box.domain, box.config, box.fluid, Vec3::Zero());
  std::vector<double>& density = box.store.find_scalar("density")->values;
  for (std::size_t i = 0; i < box.store.size(); ++i)
    density[i] = kDensity * (0.9 + 0.2 * static_cast<double>(i % 7) / 6.0);
  density[17] = 0.6 * kDensity;
  solver.step(1e-9);
  const std::vector<double>& h = box.store.find_scalar("smoothing_length")->values;
  for (std::size_t i = 0; i < box.store.size(); ++i) {
    const double expected = 1.5 * std::sqrt(box.store.mass()[i] / density[i]);
    EXPECT_NEAR(h[i], expected, 1e-12 * expected) << i;
  }
}

// 0.05 rho0 in 2D: h_i = 4.5 h.
TEST(VariableSmoothingLength, ADensityTooLowForTheSearchStopsTheRun) {
  Box box;
  SphSolver solver(box.store, box.domain, box.config, box.fluid, Vec3::Zero());
  box.store.find_scalar("density")->values[17] = 0.05 * kDensity;
  try {
    solver.step(1e-9);
    ADD_FAILURE() << "expected a RunError";
  } catch (const RunError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("variable smoothing length"));
  }
}

}  // namespace
}  // namespace partimix::sph
