// A plate turning in a circular vessel in creeping flow, 2D (cases/rotating_plate_2d.yaml): the
// plane section of the seed's validation vessel through its 30 mm plate. The torque per unit
// depth of Stokes flow in this geometry, 23.24 N m/m, comes from Taylor-Hood finite elements
// (tools/stokes_plate_reference.py: 23.740, 23.433, 23.316 with 20, 40, 80 rays a quarter turn,
// extrapolated 23.24; the same script gives the Couette torque of a circle within 1e-3).
// Asserted for the incompressible scheme with implicit viscosity (docs/power.md, "The rotating
// plate in 2D"), whose wall treatment is first order in the spacing: the error at dp = 5 mm
// (6 spacings across the plate) at most 3/4 of that at 7.5 mm (first order: 2/3), and within
// 8% of the reference (7.1%, the first-order extrapolation of the error at 7.5 mm, plus a
// margin for the time step's share below).
// Measured 2026-11-27: -10.7% and -5.1% (-19.1%, -2.1% at dp = 10 and 3.75 mm). Before the
// incompressible scheme's wall pressure was kept unfloored: -11.1% at dp = 5 mm (flow_cfl 0.2).
// Known weakness, not asserted: the torque depends on the step (at dp = 5 mm -6.3%, -5.1%,
// -2.7%, +4.3% at flow_cfl 0.05, 0.1, 0.2, 0.4), the projection's slip at the walls, which
// grows as nu dt (docs/sph.md, "Incompressible SPH").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kReferenceTorque = 23.24;  // [N m / m], Stokes flow, finite elements

// Relative error of the plate's torque against the Stokes value.
double torque_error(const std::string& spacing) {
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/rotating_plate_2d.yaml",
                    {"sph.spacing=" + spacing, "output.frames=false"});
  const test_support::CaseRun run = test_support::run_case(the_case);
  EXPECT_EQ(run.summary.status, "completed");
  const double torque = -run.figures.at("body1_torque_own");
  const double error = torque / kReferenceTorque - 1.0;
  std::printf("rotating plate, dp %s m: torque %.4f N m/m (%+.2f%% from Stokes)\n", spacing.c_str(),
              torque, 100.0 * error);
  return error;
}

TEST(RotatingPlate, IncompressibleTorqueApproachesStokesFlow) {
  const double coarse = torque_error("0.0075");
  const double fine = torque_error("0.005");
  EXPECT_LT(std::abs(fine), 0.08);
  EXPECT_LT(std::abs(fine), 0.75 * std::abs(coarse));
}

}  // namespace
}  // namespace partimix
