// Hydrostatic tank: after settling, the pressure of fluid particles follows rho0 g (H - y)
// and no fluid particle crosses a wall.
//
// Set-up: 2D tank 1.0 m wide, water 0.5 m deep, dp = 0.025 m (H / dp = 20, h = 1.5 dp),
// Wendland C2, Tait EOS, c0 = 10 sqrt(2 g H), Fourtakas delta-SPH. The viscosity is raised to
// 50 Pa s so that the start-up motion (the free-surface layer relaxing) is damped within the
// simulated 1.2 s; the hydrostatic state does not depend on it.
// Tolerances, for particles deeper than 2h (below the free-surface kernel truncation):
// largest pressure error 2.5% and RMS error 1.5% of rho0 g H. The free-surface layer settles
// about a third of a spacing higher than the initial lattice (dp / H = 5%, so ~1.5%), and the
// weak compressibility changes the density by up to 0.5% (measured with the defaults: 0.78%
// largest, 0.43% RMS). The first wall layer under the floor (Adami extrapolation) carries rho0 g (H
// + dp/2) within the same 2.5% on average (measured: 0.76%).
#include <gtest/gtest.h>

#include <cmath>

#include "app/simulation.hpp"
#include "validation/case_factory.hpp"

namespace partimix {
namespace {

// The options that change the static state: density treatment, equation of state and kernels.
// `consistency` is added to every tolerance: the deficit |1 - M| of the lattice first moment
// M = sum_j V_j (x_j - x_i) (x) grad W_ij of the gradient kernel at h = 1.5 dp (docs/sph.md,
// "Choice of h"), by which the settled pressure gradient is steeper than rho0 g. Molteni
// diffusion is not here: it diffuses the hydrostatic density gradient at the free surface and
// walls (5% error measured), which tests/sph/density_diffusion_test.cpp shows directly.
struct Variant {
  const char* name;
  void (*apply)(sph::Config&);
  double consistency;
};

const Variant kVariants[] = {
    {"fourtakas_tait_wendland", [](sph::Config&) {}, 0.0026},
    {"shepard_every_20",
     [](sph::Config& c) {
       c.density.diffusion = "none";
       c.density.shepard = true;
     },
     0.0026},
    {"linear_eos", [](sph::Config& c) { c.equation_of_state = "linear"; }, 0.0026},
    {"cubic_spline", [](sph::Config& c) { c.kernel = "cubic_spline"; }, 0.0067},
    {"hyperbolic_gradient", [](sph::Config& c) { c.gradient_kernel = "hyperbolic"; }, 0.0167},
    // The incompressible scheme sets p = 0 at the surface particles, which stand half a spacing
    // below the free surface: an offset of rho g dp / 2 = 0.025 rho g H at dp / H = 0.05; and
    // its two surface rows crowd to 0.4 of a spacing (not understood yet, issue 18), which adds up
    // to 2.7% below them (docs/sph.md, "Incompressible SPH"). Measured: max 5.2%, rms 1.5%.
    {"incompressible_shifting",
     [](sph::Config& c) {
       c.scheme = "incompressible";
       c.shifting.model = "fickian";
     },
     0.03},
};

class HydrostaticTank : public ::testing::TestWithParam<Variant> {};

TEST_P(HydrostaticTank, PressureFollowsDepthAndNoParticleCrossesTheWall) {
  const double width = 1.0;
  const double depth = 0.5;
  const double g = 9.81;
  const double rho0 = 1000.0;
  const double spacing = 0.025;
  io::Case c = testing_cases::tank_2d(width, depth, spacing);
  testing_cases::sph_of(c).fluid.rheology.viscosity = 50.0;
  GetParam().apply(testing_cases::sph_of(c).config);
  app::Simulation sim = app::build_simulation(c);

  double t = 0.0;
  while (t < 1.2) {
    const double dt = sim.methods[0].solver->stable_dt();
    sim.methods[0].solver->step(dt);
    t += dt;
  }

  const ParticleStore& store = sim.methods[0].solver->particles();
  const auto& pressure = store.find_scalar("pressure")->values;
  const double h = testing_cases::sph_of(c).config.smoothing_length();
  double worst = 0.0;
  double sum2 = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
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
  const double consistency = GetParam().consistency;
  EXPECT_LT(worst, 0.025 + consistency);
  double wall_pressure = 0.0;
  int walls = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const Vec3& x = store.position()[i];
    if (!store.is_fluid(i) && x.y() > -spacing && x.y() < 0.0 && x.x() > 0.2 && x.x() < 0.8) {
      wall_pressure += pressure[i];
      ++walls;
    }
  }
  ASSERT_GT(walls, 10);
  const double floor_exact = rho0 * g * (depth + 0.5 * spacing);
  const double floor_error = std::abs(wall_pressure / walls - floor_exact) / floor_exact;
  std::printf("hydrostatic tank: first wall layer pressure error %.4f\n", floor_error);
  EXPECT_LT(floor_error, 0.025 + consistency);
  EXPECT_LT(rms, 0.015 + consistency);
}

INSTANTIATE_TEST_SUITE_P(Options, HydrostaticTank, ::testing::ValuesIn(kVariants),
                         [](const auto& variant) { return std::string(variant.param.name); });

}  // namespace
}  // namespace partimix
