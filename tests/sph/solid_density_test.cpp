// A total Lagrangian solid's density follows its deformation gradient (docs/multi-material-sph.md,
// "Total Lagrangian solids"): a block whose particles are moved by an affine map reads
// rho0 / det(map) after the next step, at every particle, edges and corners too; the continuity
// equation, whose velocities never saw the move, would have left it at rho0. An updated
// Lagrangian block moved the same way keeps rho0, which shows the check can fail, and so does a
// fully damaged particle of the total Lagrangian block (its F may fold once it is torn away).
#include <gtest/gtest.h>

#include <vector>

#include "particles/particle_store.hpp"
#include "sph/multi_material/multi_material_solver.hpp"
#include "support/elastic_solid.hpp"
#include "support/multi_material_setup.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 1e-3;
constexpr int kSide = 10;
constexpr double kDensity = 1000.0;

constexpr std::size_t kDamaged = 44;

// The densities after a step of 1 ps taken once the block, laid at rest, is moved by `map`; its
// particle kDamaged fully damaged.
std::vector<double> densities_after_the_map(bool total_lagrangian, const Mat3& map) {
  const Domain domain = test_support::plane_domain(-0.01, -0.01, 0.03, 0.03);
  MaterialSpec solid = test_support::elastic_solid("block", kDensity, 1.0e7, 5.0e6, 0.0);
  solid.solid->total_lagrangian = total_lagrangian;
  const Config config = test_support::multi_material_config(kSpacing, {solid});
  ParticleStore store;
  test_support::square_block(store, kSide, kSpacing, kDensity);
  MultiMaterialSolver solver(store, domain, config, Vec3::Zero());
  store.find_scalar("damage")->values[kDamaged] = 1.0;
  for (Vec3& x : store.position())
    x = map * x;
  solver.step(1e-12);
  return store.find_scalar("density")->values;
}

TEST(SolidDensity, TotalLagrangianFollowsTheDeformationGradient) {
  Mat3 map = Mat3::Identity();
  map(0, 0) = 1.1;
  map(0, 1) = 0.05;
  map(1, 1) = 0.95;
  const double stretched = kDensity / map.determinant();
  const std::vector<double> total_lagrangian = densities_after_the_map(true, map);
  for (std::size_t i = 0; i < total_lagrangian.size(); ++i)
    EXPECT_NEAR(total_lagrangian[i], i == kDamaged ? kDensity : stretched, 1e-9 * kDensity) << i;
  for (const double rho : densities_after_the_map(false, map))
    EXPECT_NEAR(rho, kDensity, 1e-9 * kDensity);
}

}  // namespace
}  // namespace partimix::sph
