// The MPM solver's bookkeeping (docs/mpm.md): a block in free fall accelerates at g and stays
// stress-free; mass is conserved exactly; the run is bit for bit the same on 1 and 2 threads
// (the gather of docs/mpm.md, "Parallel loops and determinism"); a restored checkpoint
// continues bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/state_archive.hpp"
#include "support/mpm_setups.hpp"

namespace partimix::mpm {
namespace {

using test_support::box_fill;
using test_support::domain_2d;
using test_support::mpm_config;
using test_support::plane_wall;
using test_support::seed_beads;

const Vec3 kGravity(0.0, -9.81, 0.0);

// A 2D collapse: a 5 cm x 9 cm column on a rough floor, a slip wall behind it.
MpmConfig small_collapse() {
  MpmConfig config = mpm_config(0.01, seed_beads());
  config.fills = {box_fill(Vec3(0, 0, -1), Vec3(0.05, 0.09, 1), 0.005)};
  config.walls = {plane_wall(Vec3::Zero(), Vec3::UnitY(), GridBoundary::no_slip),
                  plane_wall(Vec3::Zero(), Vec3::UnitX(), GridBoundary::slip)};
  return config;
}

const Domain kCollapseDomain = domain_2d(Vec3::Zero(), Vec3(0.3, 0.12, 0.0));

TEST(MpmSolver, FreeFallAcceleratesAtGravityWithoutStress) {
  MpmConfig config = mpm_config(0.01, seed_beads());
  config.fills = {box_fill(Vec3(0.1, 0.3, -1), Vec3(0.2, 0.4, 1), 0.005)};
  ParticleStore store;
  MpmSolver solver(store, domain_2d(Vec3::Zero(), Vec3(0.3, 0.5, 0)), config, kGravity, {});
  const Vec3 start = store.position()[0];
  test_support::run_mpm(solver, 0.05);
  for (std::size_t p = 0; p < store.size(); ++p) {
    EXPECT_NEAR(store.velocity()[p].y(), -9.81 * 0.05, 1e-9);
    EXPECT_NEAR(store.velocity()[p].x(), 0.0, 1e-12);
    EXPECT_EQ(store.find_scalar("pressure")->values[p], 0.0);
  }
  // Positions move with the end-of-step velocity (symplectic Euler): y = y0 - g t^2/2 - g t dt/2.
  EXPECT_NEAR(store.position()[0].y() - start.y(), -0.5 * 9.81 * 0.05 * 0.05,
              9.81 * 0.05 * solver.stable_dt());
}

// A velocity the grid cannot hold: neighbouring columns of points move in opposite directions
// (on a periodic lattice the grid sees none of it). The transfers' filter lets it decay as
// exp(-t / tau) for any time step (docs/mpm.md, "Transfers"); tau = 0 removes it at once.
double remaining_noise(double filter_time, double dt, double end) {
  MpmConfig config = mpm_config(0.01, seed_beads(1.0));  // E = 1 Pa: no elastic forces to speak of
  config.filter_time = filter_time;
  config.fills = {box_fill(Vec3(0, 0, -1), Vec3(0.1, 0.05, 1), 0.005)};
  ParticleStore store;
  MpmSolver solver(store, domain_2d(Vec3::Zero(), Vec3(0.1, 0.05, 0), true), config, Vec3::Zero(),
                   {});
  const double u = 1e-6;
  for (std::size_t p = 0; p < store.size(); ++p) {
    const auto column = static_cast<long>(std::floor(store.position()[p].x() / 0.005));
    store.velocity()[p] = Vec3(0.0, column % 2 == 0 ? u : -u, 0.0);
  }
  while (solver.time() < end - 1e-12)
    solver.step(dt);
  double largest = 0.0;
  for (const Vec3& v : store.velocity())
    largest = std::max(largest, v.norm());
  return largest / u;
}

TEST(MpmSolver, TheTransfersFilterIsARateWhateverTheTimeStep) {
  const double tau = 0.01;
  EXPECT_NEAR(remaining_noise(tau, tau / 5, 2 * tau), std::exp(-2.0), 1e-6);
  EXPECT_NEAR(remaining_noise(tau, tau / 50, 2 * tau), std::exp(-2.0), 1e-6);
  EXPECT_LT(remaining_noise(0.0, tau / 50, tau / 50), 1e-6);
}

TEST(MpmSolver, MassIsConservedExactly) {
  ParticleStore store;
  MpmSolver solver(store, kCollapseDomain, small_collapse(), kGravity, {});
  double before = 0.0;
  for (const double m : store.mass())
    before += m;
  const std::size_t count = store.size();
  test_support::run_mpm(solver, 0.05);
  double after = 0.0;
  for (const double m : store.mass())
    after += m;
  EXPECT_EQ(store.size(), count);
  EXPECT_EQ(after, before);
  EXPECT_NEAR(before, 2200.0 * 0.05 * 0.09, 1e-9);
}

std::vector<Vec3> collapse_after(int threads, const MpmConfig& config) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  ParticleStore store;
  MpmSolver solver(store, kCollapseDomain, config, kGravity, {});
  test_support::run_mpm(solver, 0.03);
  omp_set_num_threads(saved);
  std::vector<Vec3> state = store.position();
  for (const Vec3& v : store.find_vector("stress_normal")->values)
    state.push_back(v);
  return state;
}

TEST(MpmSolver, OneAndTwoThreadsAgreeBitForBit) {
  for (const bool apic : {true, false}) {
    MpmConfig config = small_collapse();
    config.apic = apic;
    const std::vector<Vec3> one = collapse_after(1, config);
    const std::vector<Vec3> two = collapse_after(2, config);
    ASSERT_EQ(one.size(), two.size());
    for (std::size_t k = 0; k < one.size(); ++k)
      ASSERT_EQ(one[k], two[k]) << "apic " << apic << " entry " << k;
  }
}

TEST(MpmSolver, RestoredCheckpointContinuesBitForBit) {
  ParticleStore store;
  MpmSolver solver(store, kCollapseDomain, small_collapse(), kGravity, {});
  test_support::run_mpm(solver, 0.02);
  StateArchive archive;
  solver.save(archive, "methods/mpm/");
  test_support::run_mpm(solver, 0.04);

  ParticleStore copy;
  MpmSolver resumed(copy, kCollapseDomain, small_collapse(), kGravity, {});
  resumed.restore(archive, "methods/mpm/");
  test_support::run_mpm(resumed, 0.04);
  EXPECT_EQ(resumed.time(), solver.time());
  for (std::size_t p = 0; p < store.size(); ++p) {
    ASSERT_EQ(copy.position()[p], store.position()[p]);
    ASSERT_EQ(copy.velocity()[p], store.velocity()[p]);
  }
}

double total_mass(const ParticleStore& store) {
  double sum = 0.0;
  for (const double m : store.mass())
    sum += m;
  return sum;
}

TEST(MpmSolver, ExitsAndFeedsBalanceTheMass) {
  ParticleStore store;
  MpmSolver solver(store, test_support::fed_bin_domain(), test_support::fed_bin(), kGravity, {});
  const double start = total_mass(store);
  test_support::run_mpm(solver, 0.3);
  EXPECT_GT(solver.mass_out(), 0.0);
  EXPECT_GT(solver.mass_in(), 0.0);
  EXPECT_NEAR(total_mass(store) + solver.mass_out() - solver.mass_in(), start, 1e-12 * start);
  // The feed packs no more points than the lattice holds: the top of the bin (y in [0.05, 0.12],
  // 7 x 10 cm at 5 mm spacing: 280 lattice points) holds at most 2% more.
  int top = 0;
  for (const Vec3& x : store.position()) {
    EXPECT_GE(x.y(), -0.05);
    if (x.y() >= 0.05 && x.y() < 0.12)
      ++top;
  }
  EXPECT_LE(top, 1.02 * 280);
}

TEST(MpmSolver, ARestoreTakesTheSavedPointCount) {
  ParticleStore store;
  MpmSolver solver(store, test_support::fed_bin_domain(), test_support::fed_bin(), kGravity, {});
  test_support::run_mpm(solver, 0.1);
  StateArchive archive;
  solver.save(archive, "methods/mpm/");
  test_support::run_mpm(solver, 0.15);

  ParticleStore copy;
  MpmSolver resumed(copy, test_support::fed_bin_domain(), test_support::fed_bin(), kGravity, {});
  resumed.restore(archive, "methods/mpm/");
  test_support::run_mpm(resumed, 0.15);
  ASSERT_EQ(copy.size(), store.size());
  EXPECT_EQ(resumed.mass_out(), solver.mass_out());
  for (std::size_t p = 0; p < store.size(); ++p)
    ASSERT_EQ(copy.position()[p], store.position()[p]);
}

}  // namespace
}  // namespace partimix::mpm
