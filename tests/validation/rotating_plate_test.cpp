// A plate turning in a circular vessel in creeping flow, 2D (cases/rotating_plate_2d.yaml): the
// plane section of the seed's validation vessel through its 30 mm plate. The torque per unit
// depth of Stokes flow in this geometry, 23.24 N m/m, comes from Taylor-Hood finite elements
// (tools/stokes_plate_reference.py: 23.740, 23.433, 23.316 with 20, 40, 80 rays a quarter turn,
// extrapolated 23.24; the same script gives the Couette torque of a circle within 1e-3).
// Two things are asserted for the incompressible scheme with implicit viscosity (docs/power.md,
// "The rotating plate in 2D"):
// - the torque is within 9% of the reference at dp = 5 mm (6 spacings across the plate).
//   Measured 2026-11-27: -6.6%; the error falls with the spacing at first order (-16.0%,
//   -9.3%, -6.6%, -5.2%, -3.9% at dp = 10, 7.5, 5, 3.75, 2.5 mm). Before the wall pressure of the
//   incompressible scheme was kept unfloored it was -11.1% at dp = 5 mm (flow_cfl 0.2).
// - it does not depend on the time step: flow_cfl 0.4 within 3% of 0.1 (measured -2.2%). The
//   non-incremental projection's steady state moved by 10% between these two steps (its slip at
//   the walls grows as nu dt; docs/sph.md, "Incompressible SPH").
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kReferenceTorque = 23.24;  // [N m / m], Stokes flow, finite elements

double plate_torque(const std::string& flow_cfl) {
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/rotating_plate_2d.yaml",
                    {"sph.time_step.flow_cfl=" + flow_cfl, "output.frames=false"});
  const test_support::CaseRun run = test_support::run_case(the_case);
  EXPECT_EQ(run.summary.status, "completed");
  const double torque = -run.figures.at("body1_torque_own");
  std::printf("rotating plate, flow_cfl %s: torque %.4f N m/m (%+.2f%% from Stokes)\n",
              flow_cfl.c_str(), torque, 100.0 * (torque / kReferenceTorque - 1.0));
  return torque;
}

TEST(RotatingPlate, IncompressibleTorqueApproachesStokesFlowAndDoesNotDependOnTheTimeStep) {
  const double fine_step = plate_torque("0.1");
  const double long_step = plate_torque("0.4");
  EXPECT_NEAR(fine_step / kReferenceTorque, 1.0, 0.09);
  EXPECT_NEAR(long_step / fine_step, 1.0, 0.03);
}

}  // namespace
}  // namespace partimix
