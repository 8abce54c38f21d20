// Hydrostatic tank: after settling, the pressure of fluid particles follows rho0 g (H - y)
// and no fluid particle crosses a wall.
//
// Set-up: 2D tank 1.0 m wide, water 0.5 m deep, dp = 0.02 m (h = 1.3 dp), Wendland C2,
// Tait EOS, c0 = 10 sqrt(2 g H), Fourtakas delta-SPH, laminar viscosity raised to 0.5 Pa s to
// damp the start-up sloshing within the simulated 2 s (the steady state does not depend on it).
// Tolerance: the pressure of particles deeper than 2h (away from the free-surface kernel
// truncation) within 3% of rho0 g H of the exact value; in WCSPH the pressure noise at
// dp = H/25 with delta-SPH is typically 1%.
#include <gtest/gtest.h>

#include <cmath>

#include "app/simulation.hpp"
#include "validation/case_factory.hpp"

namespace partimix {
namespace {

TEST(HydrostaticTank, PressureFollowsDepthAndNoParticleCrossesTheWall) {
  const double width = 1.0;
  const double depth = 0.5;
  const double g = 9.81;
  const double rho0 = 1000.0;
  io::Case c = testing_cases::tank_2d(width, depth, 0.02);
  c.fluid.viscosity = 0.5;
  app::Simulation sim = app::build_simulation(c);

  double t = 0.0;
  while (t < 2.0) {
    const double dt = sim.solver->stable_dt();
    sim.solver->step(dt);
    t += dt;
  }

  const ParticleStore& store = sim.solver->particles();
  const auto& pressure = store.find_scalar("pressure")->values;
  const double h = 1.3 * 0.02;
  double worst = 0.0;
  double sum2 = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i)) continue;
    const Vec3& x = store.position()[i];
    EXPECT_GT(x.y(), 0.0) << "fluid particle below the tank floor";
    EXPECT_GT(x.x(), 0.0) << "fluid particle through the left wall";
    EXPECT_LT(x.x(), width) << "fluid particle through the right wall";
    const double exact = rho0 * g * (depth - x.y());
    if (depth - x.y() > 2.0 * h) {
      const double error = std::abs(pressure[i] - exact) / (rho0 * g * depth);
      worst = std::max(worst, error);
      sum2 += error * error;
      ++count;
    }
  }
  ASSERT_GT(count, 100);
  const double rms = std::sqrt(sum2 / count);
  RecordProperty("max_relative_pressure_error", std::to_string(worst));
  RecordProperty("rms_relative_pressure_error", std::to_string(rms));
  std::printf("hydrostatic tank: max error %.4f, rms error %.4f of rho g H\n", worst, rms);
  EXPECT_LT(worst, 0.03);
}

}  // namespace
}  // namespace partimix
