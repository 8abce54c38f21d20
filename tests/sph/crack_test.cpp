// A crack cuts a total Lagrangian solid (docs/multi-material-sph.md, "Total Lagrangian solids"):
// a block stretched by 1% each way pulls its two halves together with about its tension times
// its height, and once a column of fully damaged particles splits it, with nothing, since the
// bonds across the column are cut and its faces only push. Squeezed by 1% instead, the halves
// still push each other apart across the crack, within 1% of the force without it (they agree to
// 3e-8 here, the faces being the lattice the uncut block had).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "particles/particle_store.hpp"
#include "sph/kernel.hpp"
#include "sph/multi_material/multi_material_solver.hpp"
#include "sph/multi_material/total_lagrangian.hpp"
#include "sph/scaled_kernel.hpp"
#include "support/elastic_solid.hpp"
#include "support/multi_material_setup.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 1e-3;
constexpr int kSide = 11;
constexpr int kCrack = 5;  // the column that fails
constexpr double kDensity = 1000.0;
constexpr double kStep = 1e-12;

// The tension of the block stretched by 1% each way: the pressure c0^2 (rho - rho0) at
// rho = rho0 / 1.01^2 (its deviatoric stress starts at zero).
double tension_times_height(double scale) {
  const double pressure = 1.0e7 / kDensity * (kDensity / (scale * scale) - kDensity);
  return -pressure * kSide * kSpacing * scale;
}

// The total Lagrangian block laid at rest, its particles of column `failing` (none: -1) fully
// damaged, to fail at the end of the next step.
struct Block {
  explicit Block(int failing) {
    test_support::square_block(store, kSide, kSpacing, kDensity);
    solver.emplace(store, domain, config, Vec3::Zero());
    damage = &store.find_scalar("damage")->values;
    for (std::size_t k = 0; k < store.size(); ++k) {
      if (column(k, 1.0) == failing)
        (*damage)[k] = 1.0;
    }
  }
  static MaterialSpec solid() {
    MaterialSpec spec = test_support::elastic_solid("block", kDensity, 1.0e7, 5.0e6, 0.0);
    spec.solid->total_lagrangian = true;
    return spec;
  }
  // The lattice column of particle k in the block scaled by `scale`.
  int column(std::size_t k, double scale) const {
    return static_cast<int>(store.position()[k].x() / (scale * kSpacing));
  }

  Domain domain = test_support::plane_domain(-0.01, -0.01, 0.03, 0.03);
  Config config = test_support::multi_material_config(kSpacing, {solid()});
  ParticleStore store;
  std::optional<MultiMaterialSolver> solver;
  std::vector<double>* damage = nullptr;
};

// The force [N per m of depth] the left half and the middle column exert on the right half of
// the block, scaled by `scale` about the origin; with the middle column fully damaged when
// `cracked`.
double force_on_the_right_half(bool cracked, double scale) {
  Block block(cracked ? kCrack : -1);
  ParticleStore& store = block.store;
  for (Vec3& x : store.position())
    x *= scale;
  block.solver->step(kStep);  // the column fails at the step's end
  // The failed particles' density, from the continuity equation, did not see the scaling.
  std::vector<double>& density = store.find_scalar("density")->values;
  for (std::size_t k = 0; k < store.size(); ++k) {
    if ((*block.damage)[k] >= 1.0)
      density[k] = kDensity / (scale * scale);
  }
  block.solver->step(kStep);
  const std::span<const Vec3> acceleration = store.find_vector("acceleration")->values;
  Vec3 force = Vec3::Zero();
  for (std::size_t k = 0; k < store.size(); ++k) {
    if (block.column(k, scale) > kCrack)
      force += store.mass()[k] * acceleration[k];
  }
  EXPECT_NEAR(force.y(), 0.0, 1e-9 * tension_times_height(1.01));
  return force.x();
}

TEST(Crack, FailedColumnCarriesNoTensionAcrossTheBlock) {
  const double intact = force_on_the_right_half(false, 1.01);
  EXPECT_NEAR(intact, -tension_times_height(1.01), 0.1 * tension_times_height(1.01));
  const double cracked = force_on_the_right_half(true, 1.01);
  // What remains is the artificial viscosity of the faces, which the step before the crack set
  // closing at some 1e-8 m/s: 1e-9 of the tension at a step of 1 ps, 1e-10 at 0.1 ps.
  EXPECT_NEAR(cracked, 0.0, 1e-7 * std::abs(intact));
}

TEST(Crack, FacesOfTheCrackStillPushInCompression) {
  const double intact = force_on_the_right_half(false, 0.99);
  EXPECT_GT(intact, 0.0);
  EXPECT_NEAR(force_on_the_right_half(true, 0.99), intact, 0.01 * intact);
}

// Failing column 1 leaves column 0 a line of particles bonded only along it, whose B is singular
// across it: the crack loosens them, and they fail too, their damage left as it was. The
// particles beside the crack on the other side keep their bonds to the block and hold.
TEST(Crack, ParticlesLeftWithoutBondsAcrossTheLineFail) {
  ParticleStore store;
  test_support::square_block(store, kSide, kSpacing, kDensity);
  const std::size_t n = store.size();
  std::vector<double> damage(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (static_cast<int>(store.position()[k].x() / kSpacing) == 1)
      damage[k] = 1.0;
  }
  const std::vector<double> volume(n, kSpacing * kSpacing);
  const std::vector<double> h(n, 1.5 * kSpacing);
  const std::vector<std::uint8_t> bonded(n, 1);
  const std::vector<Mat3> stress(n, Mat3::Zero());
  const std::vector<double> hourglass(n, 0.0);
  const BondedParticles particles{
      store.position(), store.velocity(), store.position(), store.mass(), volume, h,
      bonded,           stress,           hourglass,        damage};
  const std::unique_ptr<Kernel> kernel = kernel_registry().create("wendland_c2");
  const ScaledKernel scaled{*kernel, 2};
  TotalLagrangianSolids solids(test_support::plane_domain(-0.01, -0.01, 0.03, 0.03), scaled,
                               1.5 * kSpacing);
  solids.refer(particles, n);
  for (std::size_t k = 0; k < n; ++k) {
    const int column = static_cast<int>(store.position()[k].x() / kSpacing);
    EXPECT_EQ(solids.failed(k), column <= 1) << k;
  }
  EXPECT_EQ(solids.loosened().size(), static_cast<std::size_t>(kSide));
}

}  // namespace
}  // namespace partimix::sph
