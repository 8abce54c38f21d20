// A sphere settling in a liquid column (cases/cfdem_settling_sphere.yaml; docs/validation.md,
// "Settling sphere"): glass, d = 2 mm, 2500 kg/m³, in a liquid of 1000 kg/m³ whose viscosity
// sets the particle Reynolds number at the terminal velocity, Re_p = 0.1, 2.1, 27 and 165. The
// reference is the drag balance (ρ_p - ρ) V g = C_d ρ (π d² / 4) v² / 2 with Schiller and
// Naumann's (1933) C_d = 24 / Re (1 + 0.15 Re^0.687), solved here by bisection. Asserted (set
// before the runs, docs/cfd-dem.md, "Tests"): one-way coupled (the fluid at rest) the velocity
// at t = 0.4 s is within 1% of it. Two-way coupled the fluid the sphere drags along lowers the
// slip, so the sphere falls faster than the balance: a known error of unresolved coupling
// (Horwitz & Mani 2016) that falls as the kernel widens; with the kernel 10 d wide it must stay
// within 5%. That bound is not derived: it was fixed after a first run of the case from the
// command line gave 3.7% at the lowest Re_p; the order of the error in Stokes flow, the
// spread force's own velocity against the sphere's, is d / b = 10% (docs/validation.md).
// One-way, the fluid force in the grains' frames (fluid_force) carries the sphere's weight m g at
// the end within 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "app/simulation.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kDiameter = 2e-3;
constexpr double kGrainDensity = 2500.0;
constexpr double kDensity = 1000.0;
constexpr double kGravity = 9.81;

double schiller_naumann_terminal_velocity(double viscosity) {
  const double weight =
      (kGrainDensity - kDensity) * std::numbers::pi * std::pow(kDiameter, 3) / 6.0 * kGravity;
  const auto excess = [&](double v) {
    const double re = kDensity * v * kDiameter / viscosity;
    const double cd = 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687));
    return weight - 0.5 * cd * kDensity * std::numbers::pi * kDiameter * kDiameter / 4.0 * v * v;
  };
  double lo = 1e-9;
  double hi = 10.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Settled {
  double velocity = 0.0;  // downward [m/s]
  double force = 0.0;     // the fluid's upward force on the sphere, its frames' fluid_force [N]
};

Settled settled(double viscosity, bool two_way) {
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfdem_settling_sphere.yaml",
                    {"output.frames=false", "fluid.viscosity=" + std::to_string(viscosity),
                     std::string("couplings[0].two_way=") + (two_way ? "true" : "false")});
  app::Simulation simulation = app::build_simulation(the_case);
  const test_support::TempDir out("settling_sphere");
  EXPECT_EQ(test_support::run_simulation(the_case, simulation, out.path()).summary.status,
            "completed");
  const ParticleStore& store = *simulation.methods[1].store;
  return {-store.velocity()[0].z(), store.find_vector("fluid_force")->values[0].z()};
}

TEST(SettlingSphere, TerminalVelocityFollowsSchillerNaumann) {
  for (const double viscosity : {0.25, 0.05, 0.01, 0.0025}) {
    const double reference = schiller_naumann_terminal_velocity(viscosity);
    const double re = kDensity * reference * kDiameter / viscosity;
    const Settled one_way_run = settled(viscosity, false);
    const double one_way = one_way_run.velocity;
    const double two_way = settled(viscosity, true).velocity;
    // At the terminal velocity the fluid's force (drag and buoyancy) carries the weight.
    const double weight =
        kGrainDensity * std::numbers::pi * std::pow(kDiameter, 3) / 6.0 * kGravity;
    EXPECT_NEAR(one_way_run.force, weight, 0.01 * weight) << "Re_p " << re;
    std::printf("Re_p %7.3f: Schiller-Naumann %.5f m/s, one-way %+.3f%%, two-way %+.3f%%\n", re,
                reference, 100.0 * (one_way / reference - 1.0),
                100.0 * (two_way / reference - 1.0));
    EXPECT_NEAR(one_way, reference, 0.01 * reference) << "Re_p " << re;
    EXPECT_NEAR(two_way, reference, 0.05 * reference) << "Re_p " << re;
  }
}

// In a liquid of 500 Pa s (a stiff paste) the sphere's relaxation time ρ_p d² / (18 μ) = 1.1 µs
// is a fifteenth of the DEM's sub-step (1 ms / 60): the DEM's kicks take the drag backward in
// time (dem/external_forces.hpp), so the sphere settles at its terminal velocity (Stokes flow,
// Re_p 3e-8), one-way within 1% of the balance at 0.4 s, and the fluid's force carries its
// weight within 1%, where the explicit kick was unstable and the coupling stopped the run. The
// velocity is measured at 0.4 s because the column's start (its pressure from zero) leaves the
// liquid moving by some 6e-7 m/s for a tenth of a second, which the sphere, locked to the liquid,
// follows (-8.8% of the 6.5 µm/s terminal velocity at 0.1 s).
TEST(SettlingSphere, TerminalVelocityWhenTheDemStepExceedsTheRelaxationTime) {
  constexpr double kViscosity = 500.0;
  const double relaxation = kGrainDensity * kDiameter * kDiameter / (18.0 * kViscosity);
  ASSERT_GT(1e-3 / 60.0, 10.0 * relaxation);
  const double reference = schiller_naumann_terminal_velocity(kViscosity);
  const Settled run = settled(kViscosity, false);
  std::printf("500 Pa s: Schiller-Naumann %.4g m/s, one-way %+.3f%%\n", reference,
              100.0 * (run.velocity / reference - 1.0));
  EXPECT_NEAR(run.velocity, reference, 0.01 * reference);
  const double weight = kGrainDensity * std::numbers::pi * std::pow(kDiameter, 3) / 6.0 * kGravity;
  EXPECT_NEAR(run.force, weight, 0.01 * weight);
}

}  // namespace
}  // namespace partimix
