// The lid-driven cavity at Re = 100 on the grid fluid (docs/cfd.md, "Tests the code will be
// held to") against Ghia, Ghia & Shin (1982), Tables I and II: u along the vertical centre-line
// and v along the horizontal one at their points inside the cavity. cases/cfd_cavity.yaml: a
// 1 x 1 m cavity, lid speed U = 1 m/s, ρ = 1, μ = 0.01 Pa s, 64 x 64 cells, van Leer's TVD
// convection, run to t = 30 L / U; steady means that the profiles at 25 and 30 s differ by less
// than 1e-3 U.
// The staggered velocities are interpolated linearly to the points. Asserted (set before the
// first run): the largest difference from Ghia within 3% of U, the root mean square within 1.5%.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "app/simulation.hpp"
#include "cfd/cfd_solver.hpp"
#include "grid/staggered_grid.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"
#include "support/ghia_cavity.hpp"

namespace partimix::cfd {
namespace {

using test_support::kGhiaU;
using test_support::kGhiaV;

constexpr int kCells = 64;

// Component `axis` at (x, y), linear between the faces of that component.
double component_at(const FluidSolver& fluid, int axis, double x, double y) {
  const grid::StaggeredGrid& grid = fluid.grid();
  const double h = grid.spacing(0);
  // The component's faces sit at whole cells along its axis and half cells across it.
  const double gx = axis == 0 ? x / h : x / h - 0.5;
  const double gy = axis == 1 ? y / h : y / h - 0.5;
  const int nx = grid.faces(axis, 0);
  const int ny = grid.faces(axis, 1);
  const int i = std::clamp(static_cast<int>(std::floor(gx)), 0, nx - 2);
  const int j = std::clamp(static_cast<int>(std::floor(gy)), 0, ny - 2);
  const double fx = gx - i;
  const double fy = gy - j;
  const std::vector<double>& u = fluid.velocity()[axis];
  auto at = [&](int a, int b) { return u[grid.face(axis, a, b, 0)]; };
  return (1 - fx) * (1 - fy) * at(i, j) + fx * (1 - fy) * at(i + 1, j) +
         (1 - fx) * fy * at(i, j + 1) + fx * fy * at(i + 1, j + 1);
}

std::array<double, 30> profiles(const FluidSolver& fluid) {
  std::array<double, 30> values{};
  for (std::size_t k = 0; k < 15; ++k) {
    values[k] = component_at(fluid, 0, 0.5, kGhiaU[k].position);
    values[15 + k] = component_at(fluid, 1, kGhiaV[k].position, 0.5);
  }
  return values;
}

// cases/cfd_cavity.yaml through the run to 25 s, then the same fluid stepped on to 30 s.
TEST(GridCavity, CentreLineVelocitiesFollowGhiaAtRe100) {
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfd_cavity.yaml",
                    {"output.frames=false", "time.end=25"});
  app::Simulation simulation = app::build_simulation(the_case);
  const test_support::TempDir out("grid_cavity");
  const test_support::CaseRun run = test_support::run_simulation(the_case, simulation, out.path());
  ASSERT_EQ(run.summary.status, "completed");
  auto& solver = dynamic_cast<CfdSolver&>(*simulation.methods[0].solver);
  const FluidSolver& fluid = solver.fluid();
  ASSERT_EQ(fluid.grid().cells(0), kCells);
  const std::array<double, 30> at_25 = profiles(fluid);
  double t = 25.0;
  std::size_t steps = run.summary.steps;
  while (t < 30.0 - 1e-9) {
    const double dt = std::min(solver.stable_dt(), 30.0 - t);
    solver.step(dt);
    t += dt;
    ++steps;
  }
  const std::array<double, 30> last = profiles(fluid);
  double largest = 0.0;
  double squares = 0.0;
  double drift = 0.0;
  for (std::size_t k = 0; k < 30; ++k) {
    const double ghia = k < 15 ? kGhiaU[k].velocity : kGhiaV[k - 15].velocity;
    const double position = k < 15 ? kGhiaU[k].position : kGhiaV[k - 15].position;
    std::printf("  %s(%.4f) = %+.5f, Ghia %+.5f, difference %+.4f\n", k < 15 ? "u" : "v", position,
                last[k], ghia, last[k] - ghia);
    largest = std::max(largest, std::abs(last[k] - ghia));
    squares += (last[k] - ghia) * (last[k] - ghia);
    drift = std::max(drift, std::abs(last[k] - at_25[k]));
  }
  const double rms = std::sqrt(squares / 30.0);
  std::printf("grid cavity Re 100, %zu steps: largest %.4f U, rms %.4f U, change 25-30 s %.2e U\n",
              steps, largest, rms, drift);
  EXPECT_LT(drift, 1e-3);
  EXPECT_LT(largest, 0.03);
  EXPECT_LT(rms, 0.015);
}

}  // namespace
}  // namespace partimix::cfd
