// A wall in translation and the analyses mass_in_region and height_profile in a run (docs/
// motions.md, docs/mixing.md): a grain of radius R = 0.01 m and mass m = 2500 (4/3) pi R^3 rests
// on a floor (the plane z = 0) that drops at 1 m/s from t = 0.05 s to t = 0.1 s, so that it ends
// 0.05 m lower. The grain falls free from t = 0.05 s, leaves the box z >= 0 (its centre below
// z = 0) at t = 0.05 + sqrt(2 R / g) = 0.095 s, and comes to rest on the lowered floor: its
// height is -0.05 + R less the contact's static overlap (below 1e-4 m).
// Samples every 0.01 s at a fixed step of 1e-4 s: M = m at t = 0 ... 0.09 and 0 at 0.10 ... 0.20,
// so the least-squares slope over the window [0, 0.2] is (t_mean = 0.1)
//   b = m sum_{k=0..9} (0.01 k - 0.1) / (1e-4 sum_{k=0..20} (k - 10)^2) = -0.55 m / 0.077,
// a discharge rate of 7.142857 m kg/s; measured to 3e-14 relative, asked 1e-6 (a sample one step
// late would move it by about 1%).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "app/simulation.hpp"
#include "support/case_run.hpp"
#include "support/temp_dir.hpp"

namespace partimix::app {
namespace {

const std::string kCase = R"(solver: dem
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.1, -0.1, -0.1]
  max: [0.1, 0.1, 0.1]
time:
  end: 0.5
  dt: 1.0e-4
  output_interval: 0.25
  sample_interval: 0.01
output:
  frames: false
dem:
  species:
    - {name: glass, density: 2500, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
  interactions:
    particle: {restitution: 0.5, friction: 0.3}
    wall: {restitution: 0.5, friction: 0.3}
  grains:
    - {position: [0.003, 0, 0.01], radius: 0.01}
walls:
  - shape: plane
    point: [0, 0, 0]
    normal: [0, 0, 1]
    motion: {type: translation, velocity: [0, 0, -1], start: 0.05, stop: 0.1}
analyses:
  - type: mass_in_region
    region: {min: [-0.05, -0.05, 0], max: [0.05, 0.05, 0.05]}
    fit_until: 0.2
  - {type: height_profile, axis: x, vertical: z, from: -0.05, to: 0.05, bins: 10}
)";

TEST(DroppingFloor, GrainFollowsTheFloorAndTheAnalysesSeeIt) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, kCase);
  Simulation simulation = build_simulation(the_case);
  const auto run = test_support::run_simulation(the_case, simulation, dir / "out");
  ASSERT_EQ(run.summary.status, "completed") << run.summary.message;
  const double radius = 0.01;
  const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  EXPECT_EQ(run.figures.at("mass_final"), 0.0);
  EXPECT_NEAR(run.figures.at("discharge_rate"), 0.55 / 0.077 * mass, 1e-6 * 0.55 / 0.077 * mass);
  EXPECT_NEAR(run.figures.at("height_max"), -0.05 + radius, 1e-4);
  EXPECT_LT(run.figures.at("height_max"), -0.05 + radius);
  EXPECT_NEAR(run.figures.at("runout"), 0.01, 1e-12);  // the bin [0, 0.01) holds x = 0.003
}

}  // namespace
}  // namespace partimix::app
