// A plate turning in a circular vessel, 2D (cases/rotating_plate_2d.yaml): the plane section of
// the seed's validation vessel through its 30 mm plate. The torque per unit depth of Stokes flow
// in this geometry, 23.24 N m/m, comes from Taylor-Hood finite elements
// (tools/plate_flow_reference.py: 23.740, 23.433, 23.316 with 20, 40, 80 rays a quarter turn,
// extrapolated 23.24; the same script gives the Couette torque of a circle within 1e-3), and
// so does the steady Navier-Stokes torque at Re = 10, 1.0605 times the Stokes one (1.0604 and
// 1.0606 with 20 and 40 rays), from inertia alone (docs/power.md, "The rotating plate in 2D").
// Asserted for the incompressible scheme with implicit viscosity, whose wall treatment is first
// order in the spacing:
// - Re = 0.5: the error at dp = 5 mm (6 spacings across the plate) at most 3/4 of that at
//   7.5 mm (first order: 2/3), and within 8% of the reference (7.1%, the first-order
//   extrapolation of the error at 7.5 mm, plus a margin for the time step's share below).
//   Measured 2026-11-27: -10.1% and -4.2% (-18.8%, -1.1%, +3.0% at dp = 10, 3.75, 2.5 mm).
// - The extrapolated ghost velocity (sph.wall_velocity: extrapolated): at dp = 7.5 mm at most
//   3/4 of the error of Adami's mirror, the gain of one refinement from 7.5 to 5 mm above (it
//   removes the wall's shift of a fraction of a spacing, the first-order part of the error).
//   Measured -5.7% against -10.1% (-12.7%, -1.3%, +1.3% at dp = 10, 5, 3.75 mm).
// - Re = 10 (the viscosity 20 times lower): within 7% of the Navier-Stokes torque at
//   dp = 5 mm. Measured -4.1%. Without the inertia the torque would be the Stokes one less the
//   spatial error, some 12% below.
// - A shear-thinning fluid (the seed's CMC power law, K = 13.9 Pa s^n, n = 0.47, bounds 0.1 and
//   40 Pa s, rho = 1000 kg/m^3, Metzner-Otto Re about 4.7): within 7% of the finite-element
//   torque 1.831 N m/m at dp = 7.5 mm (the same script with the power law by Picard iteration:
//   1.8409 and 1.8186 with 20 and 40 rays in Stokes flow, extrapolated as the Newtonian torque,
//   times 1.0153 for inertia on 20 rays). The bound: the error at a small step, -3.5% and flat
//   in the spacing, plus the step's share at flow_cfl 0.1, 2 points, plus 1.5 points for the
//   torque's fluctuation over the averaging window. Measured -5.6% (-5.4%, -5.3%, -5.5% at
//   dp = 5, 3.75, 2.5 mm: the error does not fall with the spacing, docs/power.md); with the
//   Morris operator alone, implicit viscosity's form until 2026-11-28, +11.3%.
// Known weakness, not asserted: at Re = 0.5 the torque depends on the step, the projection's
// slip at the walls, which grows as nu dt (docs/sph.md, "Incompressible SPH"): with the
// extrapolated ghost velocity -6.9%, -4.5%, -3.2% at dp = 7.5, 5, 3.75 mm and flow_cfl 0.025
// against -5.7%, -1.3%, +1.3% at the default 0.1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kStokesTorque = 23.24;          // [N m / m], finite elements
constexpr double kInertiaAtReynolds10 = 1.0605;  // Navier-Stokes over Stokes torque, Re = 10
constexpr double kShearThinningTorque = 1.831;   // [N m / m], CMC power law, finite elements

// The plate's torque per unit depth with these case overrides.
double plate_torque(const std::vector<std::string>& overrides) {
  std::vector<std::string> all_overrides{"output.frames=false"};
  all_overrides.insert(all_overrides.end(), overrides.begin(), overrides.end());
  const io::Case the_case = io::load_case(
      std::string(PARTIMIX_SOURCE_DIR) + "/cases/rotating_plate_2d.yaml", all_overrides);
  const test_support::CaseRun run = test_support::run_case(the_case);
  EXPECT_EQ(run.summary.status, "completed");
  return -run.figures.at("body1_torque_own");
}

// Relative error of the plate's torque against the Stokes value (Re = 0.5).
double torque_error(const std::string& spacing, const std::string& wall_velocity = "adami") {
  const double torque =
      plate_torque({"sph.spacing=" + spacing, "sph.wall_velocity=" + wall_velocity});
  const double error = torque / kStokesTorque - 1.0;
  std::printf("rotating plate, dp %s m, %s: torque %.4f N m/m (%+.2f%% from Stokes)\n",
              spacing.c_str(), wall_velocity.c_str(), torque, 100.0 * error);
  return error;
}

TEST(RotatingPlate, IncompressibleTorqueApproachesStokesFlow) {
  const double coarse = torque_error("0.0075");
  const double fine = torque_error("0.005");
  EXPECT_LT(std::abs(fine), 0.08);
  EXPECT_LT(std::abs(fine), 0.75 * std::abs(coarse));
  const double extrapolated = torque_error("0.0075", "extrapolated");
  EXPECT_LT(std::abs(extrapolated), 0.75 * std::abs(coarse));
}

// Re = 10 from the viscosity 20 times lower; steady in the plate's frame after about 1.5 s (the
// viscous spin-up time R^2 / nu is 10 s at Re = 10, its slowest mode about 0.7 s), so the
// torque is the mean over 1.5-2 s (-4.1%; over 3.5-4 s 0.2% lower).
TEST(RotatingPlate, IncompressibleTorqueFollowsInertiaAtReynolds10) {
  constexpr double kViscosityRatio = 20.0;
  const double torque = kViscosityRatio * plate_torque({"sph.spacing=0.005",
                                                        "fluid.viscosity=2.835", "time.end=2.0"});
  const double reference = kInertiaAtReynolds10 * kStokesTorque;
  const double error = torque / reference - 1.0;
  std::printf(
      "rotating plate, Re 10, dp 0.005 m: torque %.4f N m/m at mu = 56.7 (%+.2f%% from "
      "Navier-Stokes %.3f)\n",
      torque, 100.0 * error, reference);
  EXPECT_LT(std::abs(error), 0.07);
}

// The power law's viscosity comes from the shear rate, with the stress form's div(eta G^T) as the
// explicit part of the implicit viscous step; steady after about 0.6 s, mean over 0.7-1.2 s.
TEST(RotatingPlate, IncompressibleShearThinningTorqueFollowsTheFiniteElements) {
  const double torque = plate_torque(
      {"sph.spacing=0.0075", "time.end=1.2", "fluid.density=1000", "fluid.viscosity=null",
       "fluid.rheology={model: power_law, consistency: 13.9, flow_index: 0.47, viscosity_min: "
       "0.1, viscosity_max: 40}"});
  const double error = torque / kShearThinningTorque - 1.0;
  std::printf("rotating plate, CMC power law, dp 0.0075 m: torque %.4f N m/m (%+.2f%% from %.3f)\n",
              torque, 100.0 * error, kShearThinningTorque);
  EXPECT_LT(std::abs(error), 0.07);
}

}  // namespace
}  // namespace partimix
