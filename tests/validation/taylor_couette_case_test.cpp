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
#include <cmath>
#include <cstdio>
#include <numbers>

#include "analysis/body_load.hpp"
#include "app/simulation.hpp"
#include "couette_profile.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kInner = 0.005;
constexpr double kOuter = 0.01;
constexpr double kOmega = 2.0;
constexpr double kViscosity = 10.0;

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

double exact_angular_velocity(double r) {
  return kOmega * (kOuter * kOuter / (r * r) - 1.0) / (kOuter * kOuter / (kInner * kInner) - 1.0);
}

TEST(TaylorCouetteCase, TheCaseFileMatchesTheExactSolution) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, kCase);
  app::Simulation simulation = app::build_simulation(the_case);
  const auto run = test_support::run_simulation(the_case, simulation, dir / "out");
  ASSERT_EQ(run.summary.status, "completed") << run.summary.message;
  const ParticleStore& store = *simulation.methods[0].store;
  const double l2 = tangential_rms_error(store, exact_angular_velocity) / (kOmega * kInner);
  const auto fluid = std::count_if(store.kind().begin(), store.kind().end(), [](std::int32_t k) {
    return k == static_cast<std::int32_t>(ParticleKind::fluid);
  });
  simulation.methods[0].solver->update_body_forces();
  const double torque = 4.0 * std::numbers::pi * kViscosity * kOmega * kInner * kInner * kOuter *
                        kOuter / (kOuter * kOuter - kInner * kInner);
  const double inner =
      analysis::measure_body_load(store, 0, Vec3::Zero(), Vec3::Zero()).torque_own.z() / -torque -
      1.0;
  const double outer =
      analysis::measure_body_load(store, 1, Vec3::Zero(), Vec3::Zero()).torque_own.z() / torque -
      1.0;
  std::printf("Taylor-Couette case: %ld fluid particles, L2 %.4f, torque inner %+.4f outer %+.4f\n",
              static_cast<long>(fluid), l2, inner, outer);
  EXPECT_EQ(fluid, 943);  // sum over the ten rings of round(2 pi r / dp)
  EXPECT_LT(l2, 0.01);
  EXPECT_NEAR(inner, 0.0, 0.02);
  EXPECT_NEAR(outer, 0.0, 0.03);
}

}  // namespace
}  // namespace partimix
