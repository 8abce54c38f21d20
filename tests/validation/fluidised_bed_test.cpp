// Minimum fluidisation (cases/cfdem_fluidised_bed.yaml; docs/cfd-dem.md, "Tests";
// docs/validation.md, "CFD-DEM"): 700 glass beads (d = 1 mm, 2500 kg/m³) settled on a
// distributor in water, the water entering at the bottom at superficial velocities U from 0.5 to
// 1.6 times the minimum fluidisation velocity U_mf of Ergun's equation at the settled bed's void
// fraction ε_mf,
//
//     150 μ (1 - ε)² U / (ε³ d²) + 1.75 (1 - ε) ρ U² / (ε³ d) = (1 - ε) (ρ_p - ρ) g,
//
// (Gidaspow's law is Ergun's in the packed bed; Wen & Yu's correlation is printed beside it).
// The bed's pressure drop Δp (the pressure at the
// distributor less that 30 mm up, less the water's weight between) is averaged over the last
// 0.1 s of 0.3 s, and compared with the beads' buoyant weight per area W. Ergun's drop is taken
// over the layers of cells, each at its own mean ε of the settled bed (the bed is looser at the
// distributor and at its top), and U_mf is where it reaches W. Asserted (set before the runs):
// below U_mf Δp within 10% of Ergun's drop; above it within 10% of W; the measured U_mf, where
// the packed runs' line (Ergun's drop times their mean ratio to it) meets the fluidised runs'
// plateau, within 10% of U_mf. History: the first version took Ergun's drop at the bulk ε of the
// settled bed's height (0.452); the packed runs then sat 41% above it, because the cells' ε, which
// the drag uses, is 0.40-0.43 inside the bed. The layers' ε is the model's own, so the test
// compares with it; and it located U_mf by where the drop first reached 0.97 W, which a point at
// 0.97 W decides by chance, so it takes the classical construction instead.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "app/run_clock.hpp"
#include "app/simulation.hpp"
#include "cfd/cfd_solver.hpp"
#include "io/case.hpp"

namespace partimix {
namespace {

constexpr double kDiameter = 1e-3;
constexpr double kGrainDensity = 2500.0;
constexpr double kDensity = 1000.0;
constexpr double kViscosity = 1e-3;
constexpr double kGravity = 9.81;
constexpr double kSide = 0.008;
constexpr double kTop = 0.03;  // where the pressure above the bed is read [m]

double ergun_gradient(double eps, double u) {
  const double solid = 1.0 - eps;
  return 150.0 * kViscosity * solid * solid * u / (eps * eps * eps * kDiameter * kDiameter) +
         1.75 * solid * kDensity * u * u / (eps * eps * eps * kDiameter);
}

double ergun_minimum_fluidisation(double eps) {
  const double weight = (1.0 - eps) * (kGrainDensity - kDensity) * kGravity;
  double lo = 0.0;
  double hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (ergun_gradient(eps, mid) < weight ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The cross-section mean of a cell field in layer k.
double layer_mean(const cfd::FluidSolver& fluid, const std::vector<double>& field, int k) {
  const grid::StaggeredGrid& grid = fluid.grid();
  double sum = 0.0;
  for (int j = 0; j < grid.cells(1); ++j)
    for (int i = 0; i < grid.cells(0); ++i)
      sum += field[grid.cell(i, j, k)];
  return sum / (grid.cells(0) * grid.cells(1));
}

// p at the distributor (extrapolated from the two lowest layers) less p at kTop, less ρ g kTop.
double bed_pressure_drop(const cfd::FluidSolver& fluid) {
  const double h = fluid.grid().spacing(2);
  const double bottom =
      1.5 * layer_mean(fluid, fluid.pressure(), 0) - 0.5 * layer_mean(fluid, fluid.pressure(), 1);
  const int top = static_cast<int>(kTop / h);  // the layer whose lower face is at kTop
  const double above = 0.5 * (layer_mean(fluid, fluid.pressure(), top - 1) +
                              layer_mean(fluid, fluid.pressure(), top));
  return bottom - above - kDensity * kGravity * kTop;
}

struct BedRun {
  double pressure_drop = 0.0;         // mean over the last 0.1 s [Pa]
  std::vector<double> void_fraction;  // per layer of cells, at the end
  double height = 0.0;                // of the highest grain's top at the start [m]
  double weight = 0.0;                // buoyant weight per area [Pa]
};

// Ergun's drop over the layers of cells below kTop, each at its own ε: the drop of a packed bed
// with the model's void fraction profile at superficial velocity u.
double ergun_drop(const std::vector<double>& void_fraction, double h, double u) {
  double drop = 0.0;
  for (std::size_t k = 0; k < void_fraction.size() && (static_cast<double>(k) + 0.5) * h < kTop;
       ++k)
    drop += ergun_gradient(void_fraction[k], u) * h;
  return drop;
}

BedRun run_at(double u) {
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfdem_fluidised_bed.yaml",
                    {"output.frames=false", "time.end=0.3",
                     "cfd.sides.z-.velocity=[0, 0, " + std::to_string(u) + "]"});
  app::Simulation simulation = app::build_simulation(the_case);
  const auto& fluid = dynamic_cast<cfd::CfdSolver&>(*simulation.methods[0].solver).fluid();
  const ParticleStore& grains = *simulation.methods[1].store;
  BedRun run;
  double solid = 0.0;
  for (std::size_t i = 0; i < grains.size(); ++i) {
    solid += grains.mass()[i] / kGrainDensity;
    run.height = std::max(run.height, grains.position()[i].z() + 0.5 * kDiameter);
  }
  run.weight = solid * (kGrainDensity - kDensity) * kGravity / (kSide * kSide);
  app::RunClock clock(the_case, simulation);
  double t = 0.0;
  int samples = 0;
  std::string why;
  while (t < 0.3 - 1e-12) {
    const double dt = *clock.next_step(0.3 - t, why);
    clock.advance(t, dt);
    t += dt;
    if (t > 0.2) {
      run.pressure_drop += bed_pressure_drop(fluid);
      ++samples;
    }
  }
  run.pressure_drop /= samples;
  for (int k = 0; k < fluid.grid().cells(2); ++k)
    run.void_fraction.push_back(layer_mean(fluid, fluid.void_fraction(), k));
  return run;
}

TEST(FluidisedBed, BedLiftsAtTheMinimumFluidisationVelocity) {
  const BedRun settled = run_at(0.0);
  const double h = 0.002;
  double lo = 0.0;
  double hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (ergun_drop(settled.void_fraction, h, mid) < settled.weight ? lo : hi) = mid;
  }
  const double u_mf = 0.5 * (lo + hi);
  const double solid = settled.weight / ((kGrainDensity - kDensity) * kGravity);
  const double eps_bulk = 1.0 - solid / settled.height;
  const double ar = kDensity * (kGrainDensity - kDensity) * kGravity * std::pow(kDiameter, 3) /
                    (kViscosity * kViscosity);
  const double wen_yu =
      (std::sqrt(33.7 * 33.7 + 0.0408 * ar) - 33.7) * kViscosity / (kDensity * kDiameter);
  std::printf(
      "settled bed: top %.2f mm, eps of the layers %.3f %.3f %.3f %.3f %.3f, bulk %.3f; "
      "W %.1f Pa; U_mf: Ergun over the layers %.2f mm/s, over the bulk eps %.2f mm/s, "
      "Wen-Yu %.2f mm/s\n",
      1e3 * settled.height, settled.void_fraction[0], settled.void_fraction[1],
      settled.void_fraction[2], settled.void_fraction[3], settled.void_fraction[4], eps_bulk,
      settled.weight, 1e3 * u_mf, 1e3 * ergun_minimum_fluidisation(eps_bulk), 1e3 * wen_yu);
  // The packed runs' drop as a multiple of Ergun's, the fluidised runs' plateau, and where the
  // two meet: the measured U_mf (the classical construction of a fluidisation curve).
  double scale = 0.0;
  double plateau = 0.0;
  int packed = 0;
  int fluidised = 0;
  for (const double r : {0.5, 0.8, 0.9, 1.1, 1.2, 1.6}) {
    const BedRun run = run_at(r * u_mf);
    const double ergun = ergun_drop(settled.void_fraction, h, r * u_mf);
    std::printf("U %.2f U_mf: dp %.1f Pa = %.3f W; Ergun over the packed layers %.1f Pa\n", r,
                run.pressure_drop, run.pressure_drop / settled.weight, ergun);
    if (ergun < settled.weight)
      EXPECT_NEAR(run.pressure_drop, ergun, 0.1 * ergun) << r;
    else
      EXPECT_NEAR(run.pressure_drop, settled.weight, 0.1 * settled.weight) << r;
    if (r <= 0.8) {
      scale += run.pressure_drop / ergun;
      ++packed;
    } else if (r >= 1.2) {
      plateau += run.pressure_drop;
      ++fluidised;
    }
  }
  scale /= packed;
  plateau /= fluidised;
  lo = 0.0;
  hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (scale * ergun_drop(settled.void_fraction, h, mid) < plateau ? lo : hi) = mid;
  }
  const double measured = 0.5 * (lo + hi);
  std::printf(
      "packed drop %.3f x Ergun's, plateau %.3f W: the bed lifts at %.2f mm/s = %.3f U_mf\n", scale,
      plateau / settled.weight, 1e3 * measured, measured / u_mf);
  EXPECT_NEAR(measured, u_mf, 0.1 * u_mf);
}

}  // namespace
}  // namespace partimix
