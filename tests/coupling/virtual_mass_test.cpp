// The virtual-mass force (docs/cfd-dem.md, "The forces on a grain"): a glass sphere (d = 2 mm,
// 2500 kg/m³) released from rest in water (cases/cfdem_settling_sphere.yaml, one-way, water's
// viscosity), with and without `virtual_mass` (C_vm = 1/2). Its motion over the first 4 ms
// against the equation of motion
//
//     (m + C_vm ρ V) dv/dt = (ρ_p - ρ) V g - C_d ρ (π d² / 4) v |v| / 2,
//
// Schiller and Naumann's C_d, integrated here by RK4 (C_vm = 0 without the force): the initial
// acceleration is g (ρ_p - ρ) / (ρ_p + C_vm ρ), 4.905 m/s² against 5.886 without. The force is
// lagged by a fluid step (0.1 ms here). Asserted (set before the runs): the velocity at 4 ms
// within 1% of the equation's in both runs; and a case whose C_vm ρ / ρ_p is 1 or more is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/simulation.hpp"
#include "core/error.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix::coupling {
namespace {

constexpr double kDiameter = 2e-3;
constexpr double kGrainDensity = 2500.0;
constexpr double kDensity = 1000.0;
constexpr double kViscosity = 1e-3;
constexpr double kEnd = 0.004;

double acceleration(double v, double added) {
  const double volume = std::numbers::pi * std::pow(kDiameter, 3) / 6.0;
  const double area = std::numbers::pi * kDiameter * kDiameter / 4.0;
  const double re = kDensity * std::abs(v) * kDiameter / kViscosity;
  const double drag = re > 0.0 ? 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687)) : 0.0;
  const double force =
      (kGrainDensity - kDensity) * volume * 9.81 - 0.5 * drag * kDensity * area * v * std::abs(v);
  return force / ((kGrainDensity + added * kDensity) * volume);
}

double equation_of_motion(double added) {
  double v = 0.0;
  const double h = kEnd / 4000.0;
  for (int k = 0; k < 4000; ++k) {
    const double k1 = acceleration(v, added);
    const double k2 = acceleration(v + 0.5 * h * k1, added);
    const double k3 = acceleration(v + 0.5 * h * k2, added);
    const double k4 = acceleration(v + h * k3, added);
    v += h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
  }
  return v;
}

// `coefficient`: C_vm as the case's key says it.
std::vector<std::string> overrides(bool virtual_mass, const char* coefficient = "0.5") {
  return {"output.frames=false",
          "time.end=0.004",
          "time.dt=1.0e-4",
          "time.sub_steps.dem=6",
          "fluid.viscosity=0.001",
          "couplings[0].two_way=false",
          virtual_mass ? "couplings[0].virtual_mass=true" : "couplings[0].virtual_mass=false",
          fmt::format("couplings[0].virtual_mass_coefficient={}", coefficient)};
}

double velocity_at_end(bool virtual_mass) {
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfdem_settling_sphere.yaml",
                    overrides(virtual_mass));
  app::Simulation simulation = app::build_simulation(the_case);
  const test_support::TempDir out("virtual_mass");
  EXPECT_EQ(test_support::run_simulation(the_case, simulation, out.path()).summary.status,
            "completed");
  return -simulation.methods[1].store->velocity()[0].z();
}

TEST(VirtualMass, SlowsTheSpheresStartAsItsEquationOfMotionSays) {
  for (const bool on : {false, true}) {
    const double expected = equation_of_motion(on ? 0.5 : 0.0);
    const double measured = velocity_at_end(on);
    std::printf("virtual mass %s: v(4 ms) %.6f m/s, equation %.6f m/s (%+.3f%%)\n",
                on ? "on " : "off", measured, expected, 100.0 * (measured / expected - 1.0));
    EXPECT_NEAR(measured, expected, 0.01 * expected);
  }
}

TEST(VirtualMass, RefusesAnUnstableRatio) {
  try {
    io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfdem_settling_sphere.yaml",
                  overrides(true, "2.5"));
    ADD_FAILURE() << "C_vm rho / rho_p = 1 accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().key_path, "couplings[0].virtual_mass");
  }
}

}  // namespace
}  // namespace partimix::coupling
