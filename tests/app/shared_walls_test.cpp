// One walls section for every method (docs/case-reference.md, "walls"): the same vessel block,
// a cylinder open at the top, holds water under SPH (wall layers outside it, the fluid inside)
// and grains under DEM (settled inside it, none through its side or bottom, none lost).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix::app {
namespace {

constexpr double kRadius = 0.05;  // of the vessel [m]

const std::string kVessel = R"(walls:
  - shape: cylinder
    center: [0, 0, 0]
    radius: 0.05
    height: 0.1
    open: [z+]
    material: {youngs_modulus: 1.0e7, poisson_ratio: 0.3}
)";

const std::string kHead = R"(dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.07, -0.07, -0.02]
  max: [0.07, 0.07, 0.12]
time:
  end: 0.02
  output_interval: 0.01
)";

const std::string kWater = R"(solver: sph
sph:
  spacing: 0.005
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: cylinder, center: [0, 0, 0], radius: 0.05, height: 0.03}
)";

const std::string kGrains = R"(solver: dem
dem:
  species:
    - {name: sand, density: 2500, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
  interactions:
    particle: {restitution: 0.5, friction: 0.5}
  fill:
    region: {shape: cylinder, center: [0, 0, 0.01], radius: 0.04, height: 0.08}
    count: 150
    radius: 0.003
    settle_time: 1.5
)";

TEST(SharedWalls, TheSameVesselHoldsWaterUnderSph) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, kWater + kHead + kVessel);
  const Simulation simulation = build_simulation(the_case);
  const ParticleStore& store = *simulation.methods[0].store;
  std::size_t walls = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const Vec3& x = store.position()[i];
    const double r = std::hypot(x.x(), x.y());
    if (store.is_fluid(i)) {
      EXPECT_LT(r, kRadius);
      EXPECT_GT(x.z(), 0.0);
    } else {
      ++walls;
      EXPECT_TRUE(r > kRadius || x.z() < 0.0) << "a wall particle inside the vessel";
      EXPECT_LT(x.z(), 0.1) << "a wall particle above the open top";
    }
  }
  EXPECT_GT(walls, 1000u);
}

TEST(SharedWalls, TheSameVesselHoldsGrainsUnderDem) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, kGrains + kHead + kVessel);
  Simulation simulation = build_simulation(the_case);
  ASSERT_EQ(test_support::run_simulation(the_case, simulation, dir / "out").summary.status,
            "completed");
  const ParticleStore& store = *simulation.methods[0].store;
  const auto& radius = store.find_scalar("radius")->values;
  ASSERT_EQ(store.size(), 150u);
  double largest_speed = 0.0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const Vec3& x = store.position()[i];
    // At rest a grain under about five grains' weight (0.014 N) overlaps a neighbour or the wall
    // by (3 F / (4 E* sqrt(R)))^(2/3) = 1e-5 m, 0.4% of its radius (Hertz); 5% leaves room for
    // the bed still moving and catches any grain through the side or the floor (overlap > R).
    const double slack = 0.05 * radius[i];
    EXPECT_LT(std::hypot(x.x(), x.y()) + radius[i], kRadius + slack) << "grain " << i;
    EXPECT_GT(x.z() - radius[i], -slack) << "grain " << i;
    largest_speed = std::max(largest_speed, store.velocity()[i].norm());
  }
  EXPECT_LT(largest_speed, 0.05) << "the bed has not settled on the vessel's floor";
}

}  // namespace
}  // namespace partimix::app
