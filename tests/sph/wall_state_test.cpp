// Wall pressure of Adami, Hu and Adams (2012), eq. 27 (docs/sph.md, "Walls"): in a fluid at
// rest with constant density the pressure is linear in depth, p = p_top + rho (g - a_w).(x -
// x_top), and the extrapolation reproduces it exactly at every wall particle, whatever the
// kernel weights, also when the wall accelerates (a_w) and, with sph.negative_wall_pressure,
// where the fluid is in tension. Without that key the wall pressure is floored at zero.
// Ghost velocity (docs/sph.md, "Walls"): in a simple shear flow u = G y over the wall y = 0 the
// extrapolated form gives the linear profile's value -G d at a wall particle of depth d wherever
// its ratio d / d_f stays below the cap; Adami's mirror of the fluid's mean does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "particles/cell_grid.hpp"
#include "sph/equation_of_state.hpp"
#include "sph/kernel.hpp"
#include "sph/kernel_table.hpp"
#include "sph/wall_state.hpp"

namespace partimix::sph {
namespace {

constexpr double kDensity = 1000.0;
constexpr double kSpacing = 0.01;
constexpr double kGravity = 9.81;
constexpr int kColumns = 20;
constexpr int kFluidRows = 10;
constexpr int kWallRows = 3;

// 2D: fluid rows at y = (j + 0.5) dp, three wall rows below y = 0; fluid first in the store.
struct Tank {
  ParticleStore store;
  Domain domain;
  std::size_t fluid_count = 0;
};

void fill_tank(Tank& tank) {
  tank.domain.dimensions = 2;
  tank.domain.lo = Vec3(-0.1, -0.1, 0.0);
  tank.domain.hi = Vec3(0.3, 0.2, 0.0);
  tank.fluid_count = static_cast<std::size_t>(kColumns * kFluidRows);
  tank.store.resize(static_cast<std::size_t>(kColumns * (kFluidRows + kWallRows)));
  std::size_t k = 0;
  for (int j = -kWallRows; j < kFluidRows; ++j) {
    for (int i = 0; i < kColumns; ++i) {
      const std::size_t at =
          j >= 0 ? k++
                 : tank.fluid_count + static_cast<std::size_t>((j + kWallRows) * kColumns + i);
      tank.store.position()[at] = Vec3((i + 0.5) * kSpacing, (j + 0.5) * kSpacing, 0.0);
      tank.store.mass()[at] = kDensity * kSpacing * kSpacing;
      tank.store.kind()[at] =
          static_cast<std::int32_t>(j >= 0 ? ParticleKind::fluid : ParticleKind::wall);
    }
  }
}

// The wall state of the tank's fields (2D, Wendland C2, h = 1.5 dp, Tait); returns the kernel's
// support radius.
double update_tank_walls(const Tank& tank, Fields& fields, Parameters parameters) {
  parameters.dimensions = 2;
  parameters.reference_density = kDensity;
  const auto kernel = kernel_registry().create("wendland_c2");
  const KernelTable table(*kernel, 1.5 * kSpacing, 2);
  CellGrid grid(tank.domain, table.support_radius());
  grid.build(fields.position);
  const auto eos = equation_of_state_registry().create("tait", EosParameters{kDensity, 20.0, 7.0});
  update_wall_state(fields, tank.fluid_count, grid, table, *eos, parameters);
  return table.support_radius();
}

struct Outcome {
  double largest_error = 0.0;  // |p_w - p(y_w)| of the wall particles the fluid reaches [Pa]
  double lowest = 0.0;         // the lowest wall pressure [Pa]
};

// The fluid's pressure is p_top + rho (g_y - a_y) (y - y_top), y_top = the fill height; the wall
// particles accelerate at a_y.
Outcome wall_pressures(double p_top, double wall_acceleration, bool negative_wall_pressure) {
  Tank tank;
  fill_tank(tank);
  auto& body_acceleration = tank.store.add_vector("body_acceleration", "m/s^2").values;
  Fields fields(tank.store);
  const double top = kFluidRows * kSpacing;
  const double gradient = kDensity * (-kGravity - wall_acceleration);  // dp/dy = rho (g - a)_y
  auto pressure_at = [&](double y) { return p_top + gradient * (y - top); };
  for (std::size_t k = 0; k < tank.fluid_count; ++k) {
    fields.density[k] = kDensity;
    fields.pressure[k] = pressure_at(fields.position[k].y());
  }
  for (std::size_t k = tank.fluid_count; k < tank.store.size(); ++k)
    body_acceleration[k] = Vec3(0.0, wall_acceleration, 0.0);
  Parameters parameters;
  parameters.gravity = Vec3(0.0, -kGravity, 0.0);
  parameters.negative_wall_pressure = negative_wall_pressure;
  const double support = update_tank_walls(tank, fields, parameters);
  Outcome outcome;
  outcome.lowest = fields.pressure[tank.fluid_count];
  // Wall particles with fluid inside the kernel support (the deepest row has none).
  const double reach = support - kSpacing;
  for (std::size_t k = tank.fluid_count; k < tank.store.size(); ++k) {
    outcome.lowest = std::min(outcome.lowest, fields.pressure[k]);
    if (fields.position[k].y() > -reach)
      outcome.largest_error =
          std::max(outcome.largest_error,
                   std::abs(fields.pressure[k] - pressure_at(fields.position[k].y())));
  }
  return outcome;
}

TEST(WallState, ExtrapolatesTheHydrostaticPressureExactly) {
  const Outcome outcome = wall_pressures(0.0, 0.0, false);
  EXPECT_LT(outcome.largest_error, 1e-9 * kDensity * kGravity * kFluidRows * kSpacing);
}

TEST(WallState, IncludesTheWallsOwnAcceleration) {
  // Wall and fluid accelerating upwards at 2 g: the pressure gradient is three times the
  // hydrostatic one, and eq. 27 with g - a_w reproduces it.
  const Outcome outcome = wall_pressures(0.0, 2.0 * kGravity, false);
  EXPECT_LT(outcome.largest_error, 1e-9 * kDensity * kGravity * kFluidRows * kSpacing);
}

TEST(WallState, KeepsTensionOnlyWhenNegativeWallPressureIsAllowed) {
  // A fluid in tension: -2 rho g H at the top, so the pressure at the floor is about -rho g H.
  const double tension = -2.0 * kDensity * kGravity * kFluidRows * kSpacing;
  const Outcome allowed = wall_pressures(tension, 0.0, true);
  EXPECT_LT(allowed.largest_error, 1e-9 * std::abs(tension));
  EXPECT_LT(allowed.lowest, 0.4 * tension);
  const Outcome floored = wall_pressures(tension, 0.0, false);
  EXPECT_EQ(floored.lowest, 0.0);
}

// The ghost velocities of the wall particles in the shear flow u = (G y, 0, 0), and the depth d of
// each, by wall row (0: the row next to the fluid).
struct ShearGhosts {
  std::vector<std::vector<double>> ghost_over_depth;  // u_ghost / (-G d) by row
};

ShearGhosts shear_ghosts(bool extrapolated) {
  constexpr double kShearRate = 3.0;
  Tank tank;
  fill_tank(tank);
  auto& depth = tank.store.add_scalar("surface_depth", "m").values;
  auto& normal = tank.store.add_vector("surface_normal", "").values;
  Fields fields(tank.store);
  for (std::size_t k = 0; k < tank.store.size(); ++k) {
    fields.density[k] = kDensity;
    const double y = fields.position[k].y();
    fields.velocity[k] = k < tank.fluid_count ? Vec3(kShearRate * y, 0.0, 0.0) : Vec3::Zero();
    depth[k] = std::max(-y, 0.0);
    normal[k] = Vec3::UnitY();
  }
  Parameters parameters;
  parameters.extrapolated_wall_velocity = extrapolated;
  update_tank_walls(tank, fields, parameters);
  ShearGhosts ghosts;
  ghosts.ghost_over_depth.resize(kWallRows);
  for (std::size_t k = tank.fluid_count; k < tank.store.size(); ++k) {
    const int row = static_cast<int>(std::floor(-fields.position[k].y() / kSpacing));
    ghosts.ghost_over_depth[static_cast<std::size_t>(row)].push_back(fields.wall_velocity[k].x() /
                                                                     (-kShearRate * depth[k]));
  }
  return ghosts;
}

TEST(WallState, ExtrapolatedGhostVelocityFollowsTheLinearProfile) {
  // h = 1.5 dp. The row at depth 0.5 dp sees the fluid rows at 0.5 and 1.5 dp: d / d_f is below
  // the cap of 2 and the ghost is -G d exactly. The row at 1.5 dp sees only the fluid row at
  // 0.5 dp (d / d_f = 3): capped, -2 G (0.5 dp), 2/3 of -G d.
  const ShearGhosts extrapolated = shear_ghosts(true);
  for (double ratio : extrapolated.ghost_over_depth[0])
    EXPECT_NEAR(ratio, 1.0, 1e-9);
  for (double ratio : extrapolated.ghost_over_depth[1])
    EXPECT_NEAR(ratio, 2.0 / 3.0, 1e-9);
  // Adami's mirror -G d_f gives the first row the fluid's mean distance instead of its depth:
  // 15% off.
  const ShearGhosts mirrored = shear_ghosts(false);
  EXPECT_GT(std::abs(mirrored.ghost_over_depth[0][kColumns / 2] - 1.0), 0.1);
}

}  // namespace
}  // namespace partimix::sph
