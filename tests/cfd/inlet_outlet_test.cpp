// A channel with an inlet and an outlet (docs/cfd.md, "Inlets and outlets"): 2D, height H = 1 m
// of 16 cells, length 8 H, a uniform inflow U = 1 m/s at x = 0, a pressure outlet at x = 8 H,
// no-slip walls at y = 0 and H, ν = 0.1 m²/s (Re = U H / ν = 10, entrance length about
// 0.05 Re H + 0.5 H = H). Downstream the flow is plane Poiseuille flow: peak 1.5 U, pressure
// gradient -12 μ U / H². Asserted: the mass flow out equals the mass flow in to the pressure
// solve's tolerance (1e-8 relative), the peak at x = 6 H within 1% of 1.5 U (the 16-cell
// profile's own error is 0.39%), the pressure gradient between x = 4 H and 6 H within 2% of
// Poiseuille's, and the pressure at the outlet's cells half a cell's gradient above zero.
#include <gtest/gtest.h>

#include <cmath>

#include "cfd/fluid_solver.hpp"
#include "grid/staggered_grid.hpp"
#include "support/fluid_steps.hpp"

namespace partimix::cfd {
namespace {

constexpr int kCells = 16;
constexpr double kNu = 0.1;

TEST(InletOutlet, ChannelBecomesPoiseuilleFlowDownstream) {
  const double h = 1.0 / kCells;
  const grid::StaggeredGrid grid(2, Vec3::Zero(), {8 * kCells, kCells, 1}, Vec3(h, h, 1.0), {},
                                 1e6);
  BoxSides sides;
  sides[0].velocity = Vec3(1.0, 0.0, 0.0);  // x-: the inlet
  sides[1].outlet = true;                   // x+
  FluidSettings settings;
  settings.density = 1.0;
  settings.rheology.viscosity = kNu;
  settings.max_dt = 0.05;
  FluidSolver fluid(grid, open_mask(grid), sides, settings);
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

}  // namespace
}  // namespace partimix::cfd
