// Plane Poiseuille flow on the grid fluid (docs/cfd.md, "Tests the code will be held to"): a
// channel of height H periodic along x, no-slip walls at y = 0 and H, driven by a body force g
// along x. The steady profile is u(y) = g y (H - y) / (2 ν) (peak g H² / (8 ν)). The staggered
// grid's three-point Laplacian with the ghost value behind each wall is second order: the largest
// error falls four times when the cells halve (the discrete steady solution's largest error is
// (h / H)² of the peak, 1/256 on 16 cells: the wall row's three-point difference misses the
// parabola's by a quarter). Asserted: the error on 16 cells across within 0.5% of the peak,
// and the ratio of the errors on 16 and 32 cells within 3.9-4.1.
#include <gtest/gtest.h>

#include <cmath>

#include "cfd/fluid_solver.hpp"
#include "grid/staggered_grid.hpp"
#include "support/fluid_steps.hpp"

namespace partimix::cfd {
namespace {

constexpr double kHeight = 1.0;
constexpr double kNu = 1.0;
constexpr double kForce = 8.0;  // peak speed g H² / (8 ν) = 1 m/s

// The largest |u - exact| over the cells at t = 3 H² / ν (the slowest mode decays as
// exp(-π² ν t / H²)), relative to the peak.
double steady_error(int cells) {
  const double h = kHeight / cells;
  const grid::StaggeredGrid grid(2, Vec3::Zero(), {4, cells, 1}, Vec3(h, h, 1.0),
                                 {true, false, false}, 1e6);
  FluidSettings settings;
  settings.density = 1.0;
  settings.rheology.viscosity = kNu;
  settings.gravity = Vec3(kForce, 0.0, 0.0);
  settings.max_dt = 0.05;
  FluidSolver fluid(grid, open_mask(grid), BoxSides{}, settings);
  test_support::step_fluid_until(fluid, 3.0 * kHeight * kHeight / kNu);
  double error = 0.0;
  for (int j = 0; j < cells; ++j) {
    const double y = (j + 0.5) * h;
    const double exact = kForce * y * (kHeight - y) / (2.0 * kNu);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(fluid.cell_velocity(i, j, 0).y(), 0.0, 1e-10);
      error = std::max(error, std::abs(fluid.cell_velocity(i, j, 0).x() - exact));
    }
  }
  return error / (kForce * kHeight * kHeight / (8.0 * kNu));
}

TEST(PoiseuilleFlow, SteadyProfileIsTheParabolaToSecondOrder) {
  const double coarse = steady_error(16);
  const double fine = steady_error(32);
  std::printf("Poiseuille: largest error %.3e (16 cells), %.3e (32 cells), ratio %.2f\n", coarse,
              fine, coarse / fine);
  EXPECT_LT(coarse, 5e-3);
  EXPECT_GT(coarse / fine, 3.9);
  EXPECT_LT(coarse / fine, 4.1);
}

}  // namespace
}  // namespace partimix::cfd
