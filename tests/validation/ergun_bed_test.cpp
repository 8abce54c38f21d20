// A fixed packed bed against Ergun's equation (cases/cfdem_ergun_bed.yaml; docs/cfd-dem.md,
// "Tests"; docs/validation.md, "CFD-DEM"): water up through 625 spheres of d = 1 mm on a cubic
// lattice of 1.2 mm, at superficial velocities U = 0.001, 0.01 and 0.05 m/s (Re_p = ρ U d / μ =
// 1, 10, 50). With Gidaspow's law (Ergun's branch below ε = 0.8) the steady fluid momentum in a
// uniform bed is ε dp/dz = -β U / ε, so the pressure gradient is Ergun's (1952)
//
//     -dp/dz = 150 μ (1 - ε)² U / (ε³ d²) + 1.75 (1 - ε) ρ U² / (ε³ d)
//
// at the bed's ε. Measured: the gradient of the cross-section mean pressure between the cells
// 6 mm inside each end of the bed (where the kernel's edge no longer reaches), against Ergun's
// at the mean ε of those cells. Asserted: within 2% at each U (set before the runs); the grains
// stay put (less than 1e-5 d: a sanity check; at a density of 2.5e9 the first run moved them
// 1e-3 d, so the case's density was raised to 2.5e12).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "app/simulation.hpp"
#include "cfd/cfd_solver.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kDiameter = 1e-3;
constexpr double kViscosity = 1e-3;
constexpr double kDensity = 1000.0;
constexpr double kBedLow = 0.0100;   // the lowest grains' bottom [m]
constexpr double kBedHigh = 0.0394;  // the highest grains' top [m]

double ergun_gradient(double eps, double u) {
  const double solid = 1.0 - eps;
  return 150.0 * kViscosity * solid * solid * u / (eps * eps * eps * kDiameter * kDiameter) +
         1.75 * solid * kDensity * u * u / (eps * eps * eps * kDiameter);
}

struct Layer {
  double z = 0.0;
  double pressure = 0.0;
  double void_fraction = 0.0;
};

// The cross-section means of layer k of cells.
Layer layer(const cfd::FluidSolver& fluid, int k) {
  const grid::StaggeredGrid& grid = fluid.grid();
  Layer l;
  const int cells = grid.cells(0) * grid.cells(1);
  for (int j = 0; j < grid.cells(1); ++j)
    for (int i = 0; i < grid.cells(0); ++i) {
      l.pressure += fluid.pressure()[grid.cell(i, j, k)] / cells;
      l.void_fraction += fluid.void_fraction()[grid.cell(i, j, k)] / cells;
    }
  l.z = grid.cell_centre(0, 0, k).z();
  return l;
}

TEST(ErgunBed, PressureGradientFollowsErgun) {
  for (const double u : {0.001, 0.01, 0.05}) {
    const io::Case the_case = io::load_case(
        std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfdem_ergun_bed.yaml",
        {"output.frames=false", "cfd.sides.z-.velocity=[0, 0, " + std::to_string(u) + "]"});
    app::Simulation simulation = app::build_simulation(the_case);
    const ParticleStore& grains = *simulation.methods[1].store;
    const std::vector<Vec3> start = grains.position();
    const test_support::TempDir out("ergun_bed");
    ASSERT_EQ(test_support::run_simulation(the_case, simulation, out.path()).summary.status,
              "completed");
    const auto& fluid = dynamic_cast<cfd::CfdSolver&>(*simulation.methods[0].solver).fluid();
    int first = -1;
    int last = -1;
    double eps = 0.0;
    for (int k = 0; k < fluid.grid().cells(2); ++k) {
      const Layer l = layer(fluid, k);
      if (l.z < kBedLow + 0.006 || l.z > kBedHigh - 0.006)
        continue;
      first = first < 0 ? k : first;
      last = k;
      eps += l.void_fraction;
    }
    eps /= last - first + 1;
    const Layer low = layer(fluid, first);
    const Layer high = layer(fluid, last);
    const double gradient = -(high.pressure - low.pressure) / (high.z - low.z);
    const double ergun = ergun_gradient(eps, u);
    double moved = 0.0;
    for (std::size_t i = 0; i < grains.size(); ++i)
      moved = std::max(moved, (grains.position()[i] - start[grains.id()[i]]).norm());
    std::printf(
        "U %.3f m/s: eps %.4f, -dp/dz %.2f Pa/m, Ergun %.2f Pa/m (%+.2f%%), grains moved "
        "%.1e m\n",
        u, eps, gradient, ergun, 100.0 * (gradient / ergun - 1.0), moved);
    EXPECT_NEAR(gradient, ergun, 0.02 * ergun) << "U " << u;
    EXPECT_LT(moved, 1e-5 * kDiameter);
  }
}

}  // namespace
}  // namespace partimix
