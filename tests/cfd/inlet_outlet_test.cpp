// A channel with an inlet and an outlet (docs/cfd.md, "Inlets and outlets"): 2D, height H = 1 m
// of 16 cells, length 8 H, a uniform inflow U = 1 m/s at x = 0, a pressure outlet at x = 8 H,
// no-slip walls at y = 0 and H, ν = 0.1 m²/s (Re = U H / ν = 10, entrance length about
// 0.05 Re H + 0.5 H = H). Downstream the flow is plane Poiseuille flow: peak 1.5 U, pressure
// gradient -12 μ U / H². Asserted: the mass flow out equals the mass flow in to the pressure
// solve's tolerance (1e-8 relative), the peak at x = 6 H within 1% of 1.5 U (the 16-cell
// profile's own error is 0.39%), the pressure gradient between x = 4 H and 6 H within 2% of
// Poiseuille's, and the pressure at the outlet's cells half a cell's gradient above zero.
//
// A uniform oblique flow (U, V) = (1, 0.5) m/s through the same box, periodic across, in from
// the inlet and out through the outlet, is an exact solution: after 4 s (64 passages of a cell)
// every face keeps it to 1e-9. Before 2026-11-30 the momentum's convection left out the flux
// through the outlet side of the last cells' cross faces, so that there V grew as exp(U t / h)
// (the truck drum's 4-6 m/s jets of air past the opening, which set its time step).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cfd/fluid_solver.hpp"
#include "grid/staggered_grid.hpp"
#include "support/fluid_steps.hpp"

namespace partimix::cfd {
namespace {

constexpr int kCells = 16;
constexpr double kNu = 0.1;

// A fluid of unit density and ν = kNu on `grid`, an inlet at x- bringing `inflow`, an outlet at
// x+.
FluidSolver channel(const grid::StaggeredGrid& grid, const Vec3& inflow) {
  BoxSides sides;
  sides[0].velocity = inflow;
  sides[1].outlet = true;
  FluidSettings settings;
  settings.density = 1.0;
  settings.rheology.viscosity = kNu;
  settings.max_dt = 0.05;
  return FluidSolver(grid, open_mask(grid), sides, settings);
}

TEST(InletOutlet, ChannelBecomesPoiseuilleFlowDownstream) {
  const double h = 1.0 / kCells;
  const grid::StaggeredGrid grid(2, Vec3::Zero(), {8 * kCells, kCells, 1}, Vec3(h, h, 1.0), {},
                                 1e6);
  FluidSolver fluid = channel(grid, Vec3(1.0, 0.0, 0.0));
  test_support::step_fluid_until(fluid, 24.0);
  double in = 0.0;
  double out = 0.0;
  for (int j = 0; j < kCells; ++j) {
    in += fluid.velocity()[0][grid.face(0, 0, j, 0)] * h;
    out += fluid.velocity()[0][grid.face(0, 8 * kCells, j, 0)] * h;
  }
  EXPECT_NEAR(out, in, 1e-8 * in);
  // The peak: the mean of the two faces nearest the centre line at x = 6 H.
  const int at = 6 * kCells;
  const double peak = 0.5 * (fluid.velocity()[0][grid.face(0, at, kCells / 2 - 1, 0)] +
                             fluid.velocity()[0][grid.face(0, at, kCells / 2, 0)]);
  const auto mean_pressure = [&](int i) {
    double sum = 0.0;
    for (int j = 0; j < kCells; ++j)
      sum += fluid.pressure()[grid.cell(i, j, 0)];
    return sum / kCells;
  };
  const double gradient = (mean_pressure(6 * kCells) - mean_pressure(4 * kCells)) / 2.0;
  const double poiseuille = -12.0 * kNu * 1.0;  // -12 μ U / H² with ρ = 1
  std::printf("inflow %.12f, outflow %.12f, peak %.5f U, dp/dx %.5f (Poiseuille %.5f)\n", in, out,
              peak, gradient, poiseuille);
  EXPECT_NEAR(peak, 1.5, 0.015);
  EXPECT_NEAR(gradient, poiseuille, 0.02 * std::abs(poiseuille));
  // The outlet's cells lie half a cell upstream of p = 0.
  EXPECT_NEAR(mean_pressure(8 * kCells - 1), -0.5 * h * poiseuille,
              0.05 * std::abs(h * poiseuille));
}

TEST(InletOutlet, UniformObliqueFlowLeavesUnchanged) {
  const double h = 1.0 / kCells;
  const grid::StaggeredGrid grid(2, Vec3::Zero(), {kCells, kCells, 1}, Vec3(h, h, 1.0),
                                 {false, true, false}, 1e6);
  const Vec3 flow(1.0, 0.5, 0.0);
  FluidSolver fluid = channel(grid, flow);
  FaceArrays velocity = face_arrays(grid, 0.0);
  for (int a = 0; a < 2; ++a)
    velocity[a].assign(velocity[a].size(), flow[a]);
  fluid.restore(velocity, std::vector<double>(grid.cell_count(), 0.0),
                std::vector<double>(grid.cell_count(), 0.0),
                std::vector<double>(grid.cell_count(), 1.0));
  test_support::step_fluid_until(fluid, 4.0);
  double worst = 0.0;
  for (int a = 0; a < 2; ++a)
    for (const double u : fluid.velocity()[a])
      worst = std::max(worst, std::abs(u - flow[a]));
  std::printf("largest departure from the uniform flow: %.3e m/s\n", worst);
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace partimix::cfd
