// Circular Couette flow in 3D (issue 18: a check written outside the project found the torque on
// a turning inner cylinder 16% low in a 3D slab while the flow was right): a slab periodic along
// the axis, 5 mm thick (ten layers; at least three kernel supports), R1 = 5 mm turning at Omega = 2
// rad/s, R2 = 10 mm at rest (a drum wall), gap / dp = 10, mu = 10 Pa s, the Newtonian default
// (the Morris operator), particles on rings (sph.lattice polar). Exact (Bird, Stewart and
// Lightfoot 2002, example 3.6-3): omega(r) = Omega (R2^2 / r^2 - 1) / (R2^2 / R1^2 - 1) and the
// torque 4 pi mu Omega R1^2 R2^2 / (R2^2 - R1^2) per unit length on each cylinder. Steady after
// 1.5 ms (the torques move by less than 0.1% from 2 to 6 ms).
//
// The Morris term carries only eta G . n to a wall; at a turning wall the other part of the
// traction, eta G^T . n = eta n x omega (docs/power.md, "Viscous traction"), is 3/8 of the torque
// here. Estimated from the fluid's stresses near the wall, it came out 16% low (the inner torque
// -6.6%); taken at its exact wall value, the inner torque is -0.5% and the outer -1.7%
// (2026-11-26). On the Cartesian lattice (the report's set-up) the fluid also kept half a
// spacing off the cylinder's surface, which left an empty band along it (-14.9% with both
// defects); with the fluid on every lattice point outside the body (sph/body_clearance.hpp) the
// inner torque is +1.6% and the outer -0.03%. Tolerances: the issue's 2% for the turning body,
// 3% for the wall at rest, L2 of v_theta within 1% of Omega R1 (0.30% and 0.90%).
#include <gtest/gtest.h>

#include <cstdio>

#include "app/simulation.hpp"
#include "couette_profile.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kThickness = 0.005;

// The case on rings (sph.lattice polar) or, without `lattice`, on the default Cartesian lattice.
std::string slab_case(const std::string& lattice) {
  return R"(name: taylor_couette_3d
solver: sph
dimensions: 3
domain: {min: [-0.015, -0.015, 0.0], max: [0.015, 0.015, 0.005], periodic: [z]}
time: {end: 0.002, output_interval: 0.002}
output: {frames: false}
sph:
  spacing: 0.0005
  max_velocity: 0.01
)" + lattice +
         R"(
fluid:
  density: 1000
  viscosity: 10
  regions:
    - {shape: cylinder, center: [0, 0, -0.01], radius: 0.01, height: 0.03}
walls:
  - {shape: cylinder, center: [0, 0, -0.01], radius: 0.005, height: 0.03, solid: true,
     motion: {type: rotation, axis: [0, 0, 1], axis_point: [0, 0, 0], rpm: 19.098593171027442}}
  - {shape: drum, axis_point: [0, 0, 0], axis: [0, 0, 1], radius: 0.01}
)";
}

TaylorCouetteErrors run_slab(const std::string& lattice) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, slab_case(lattice));
  app::Simulation simulation = app::build_simulation(the_case);
  const auto run = test_support::run_simulation(the_case, simulation, dir / "out");
  EXPECT_EQ(run.summary.status, "completed") << run.summary.message;
  simulation.methods[0].solver->update_body_forces();
  const TaylorCouetteErrors e = taylor_couette_errors(
      *simulation.methods[0].store, {kTaylorCouette.inner, kTaylorCouette.outer,
                                     kTaylorCouette.omega, kTaylorCouette.viscosity, kThickness});
  std::printf("Taylor-Couette 3D (%s): L2 %.4f, torque inner %+.4f outer %+.4f\n",
              lattice.empty() ? "Cartesian" : "rings", e.l2, e.inner, e.outer);
  return e;
}

TEST(TaylorCouette3d, TheTurningCylindersTorqueIsAsAccurateAsTheOneAtRest) {
  const TaylorCouetteErrors e = run_slab("  lattice: {type: polar, centre: [0, 0, 0]}");
  EXPECT_LT(e.l2, 0.01);
  EXPECT_NEAR(e.inner, 0.0, 0.02);
  EXPECT_NEAR(e.outer, 0.0, 0.03);
}

TEST(TaylorCouette3d, OnTheCartesianLatticeToo) {
  // The issue's report: this set-up gave the inner torque 16% low.
  const TaylorCouetteErrors e = run_slab("");
  EXPECT_LT(e.l2, 0.01);
  EXPECT_NEAR(e.inner, 0.0, 0.02);
  EXPECT_NEAR(e.outer, 0.0, 0.03);
}

}  // namespace
}  // namespace partimix
