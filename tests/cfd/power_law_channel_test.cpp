// A power-law fluid in a plane channel on the grid fluid (docs/cfd.md, "Non-Newtonian
// viscosity"): height H = 1 m periodic along x, no-slip walls at y = 0 and H, driven by a body
// force g along x, ρ = 1, consistency K = 1 Pa s^n, flow index n = 0.5 (shear-thinning), the
// viscosity capped at 100 Pa s. The steady profile (Bird, Armstrong & Hassager 1987, ch. 4) is
//
//     u(s) = n / (n + 1) (ρ g / K)^(1/n) ((H/2)^((n+1)/n) - s^((n+1)/n)),   s = |y - H/2|,
//
// with g = 4.899 m/s² giving a peak of 1 m/s. The viscosity is the cells' η(γ̇) from the last
// step's velocity. Asserted (set before the run): on 32 cells across, the peak within 2% and the
// largest error over the cells within 3% of the peak at t = 20 s; and the flow's transverse
// velocity stays zero.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cfd/fluid_solver.hpp"
#include "grid/staggered_grid.hpp"
#include "support/fluid_steps.hpp"

namespace partimix::cfd {
namespace {

constexpr int kCells = 32;
constexpr double kForce = 4.899;
constexpr double kIndex = 0.5;

double exact(double y) {
  const double s = std::abs(y - 0.5);
  const double e = (kIndex + 1.0) / kIndex;
  return kIndex / (kIndex + 1.0) * std::pow(kForce, 1.0 / kIndex) *
         (std::pow(0.5, e) - std::pow(s, e));
}

TEST(PowerLawChannel, SteadyProfileFollowsTheAnalyticalSolution) {
  const double h = 1.0 / kCells;
  const grid::StaggeredGrid grid(2, Vec3::Zero(), {4, kCells, 1}, Vec3(h, h, 1.0),
                                 {true, false, false}, 1e6);
  FluidSettings settings;
  settings.density = 1.0;
  settings.rheology.model = "power_law";
  settings.rheology.consistency = 1.0;
  settings.rheology.flow_index = kIndex;
  settings.rheology.viscosity_max = 100.0;
  settings.gravity = Vec3(kForce, 0.0, 0.0);
  settings.max_dt = 0.05;
  FluidSolver fluid(grid, open_mask(grid), BoxSides{}, settings);
  test_support::step_fluid_until(fluid, 20.0);
  double error = 0.0;
  double peak = 0.0;
  for (int j = 0; j < kCells; ++j) {
    const Vec3 u = fluid.cell_velocity(1, j, 0);
    EXPECT_NEAR(u.y(), 0.0, 1e-10);
    error = std::max(error, std::abs(u.x() - exact((j + 0.5) * h)));
    peak = std::max(peak, u.x());
  }
  // The peak lies between the two middle cells: read it from the face values at y = H/2.
  const double centre = 0.5 * (fluid.cell_velocity(1, kCells / 2 - 1, 0).x() +
                               fluid.cell_velocity(1, kCells / 2, 0).x());
  std::printf(
      "power-law channel, n = 0.5, 32 cells: largest error %.4f of the peak, centre %.5f "
      "(exact %.5f; the two middle cells' mean)\n",
      error / exact(0.5), centre, exact(0.5));
  EXPECT_NEAR(peak, exact(0.5), 0.02 * exact(0.5));
  EXPECT_LT(error, 0.03 * exact(0.5));
}

}  // namespace
}  // namespace partimix::cfd
