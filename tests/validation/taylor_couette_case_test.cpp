// Circular Couette flow set up from a case file (issue 15: a user could not say a 2D annulus or
// particles on rings): 2D circles as walls (`shape: cylinder` in 2D), the inner one solid and in
// rotation, a fluid circle less the inner body, and the polar lattice (`sph.lattice`). The case
// lays the same rings as tests/validation/taylor_couette_test.cpp builds in code (R1 = 5 mm,
// R2 = 10 mm, gap / dp = 10, Omega = 2 rad/s, mu = 10 Pa s, Morris operator), and is held to that
// test's Newtonian tolerances against the exact solution omega(r) = Omega (R2^2 / r^2 - 1) /
// (R2^2 / R1^2 - 1) and torque per length 4 pi mu Omega R1^2 R2^2 / (R2^2 - R1^2) (Bird, Stewart
// and Lightfoot 2002, example 3.6-3): L2 of v_theta within 1% of Omega R1, the outer torque within
// 3%, the inner within 2% (the issue's bound for a turning body). Measured (2026-11-26): L2
// 0.29%, inner -0.87%, outer -2.16%, as the code-built set-up gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "app/simulation.hpp"
#include "couette_profile.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

const std::string kCase = R"(name: taylor_couette_2d
solver: sph
dimensions: 2
domain: {min: [-0.015, -0.015], max: [0.015, 0.015]}
time: {end: 0.01, output_interval: 0.01}
output: {frames: false}
sph:
  spacing: 0.0005
  max_velocity: 0.01
  viscous_operator: morris
  lattice: {type: polar, centre: [0, 0]}
fluid:
  density: 1000
  viscosity: 10
  regions:
    - {shape: cylinder, center: [0, 0], radius: 0.01}
walls:
  - {shape: cylinder, center: [0, 0], radius: 0.005, solid: true,
     motion: {type: rotation, rpm: 19.098593171027442}}
  - {shape: cylinder, center: [0, 0], radius: 0.01}
)";

TEST(TaylorCouetteCase, TheCaseFileMatchesTheExactSolution) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, kCase);
  app::Simulation simulation = app::build_simulation(the_case);
  const auto run = test_support::run_simulation(the_case, simulation, dir / "out");
  ASSERT_EQ(run.summary.status, "completed") << run.summary.message;
  const ParticleStore& store = *simulation.methods[0].store;
  const auto fluid = std::count_if(store.kind().begin(), store.kind().end(), [](std::int32_t k) {
    return k == static_cast<std::int32_t>(ParticleKind::fluid);
  });
  simulation.methods[0].solver->update_body_forces();
  const TaylorCouetteErrors e = taylor_couette_errors(store, kTaylorCouette);
  std::printf("Taylor-Couette case: %ld fluid particles, L2 %.4f, torque inner %+.4f outer %+.4f\n",
              static_cast<long>(fluid), e.l2, e.inner, e.outer);
  EXPECT_EQ(fluid, 943);  // sum over the ten rings of round(2 pi r / dp)
  EXPECT_LT(e.l2, 0.01);
  EXPECT_NEAR(e.inner, 0.0, 0.02);
  EXPECT_NEAR(e.outer, 0.0, 0.03);
}

}  // namespace
}  // namespace partimix
