// The 2D Taylor-Green vortex at Re = U L / nu = 100 (Taylor & Green 1937; the SPH form of Adami,
// Hu & Adams 2013, section 4.1): in the periodic unit square
//   u = -U e^(b t) cos(2 pi x) sin(2 pi y),  v = U e^(b t) sin(2 pi x) cos(2 pi y),
//   p = -rho U^2 e^(2 b t) (cos(4 pi x) + cos(4 pi y)) / 4,  b = -8 pi^2 nu / L^2,
// the largest speed decays as e^(b t). Morris viscosity, h = 1.5 dp, 50 x 50 particles, to
// t = 2 s (e^(b t) = 0.21), with Fickian shifting (docs/sph.md, "Particle shifting").
// - Weakly compressible, c0 = 10 U. Asserted: the decay rate fitted to the largest speed over
//   0.25-2 s within 3% of b (the Morris term's regularisation alone makes the viscosity about 2%
//   low: docs/sph.md, "Viscosity"), and the L2 velocity error at 2 s below 5% of U e^(b t).
//   Measured: -0.1% and 2.8%; without shifting the particles cluster at the stagnation points
//   and the vortex loses 30% of its speed by t = 0.4 s (L2 error 0.59 at 2 s; docs/sph.md).
// - Incompressible (projection), dt = 0.1 h / U, five times the weakly-compressible step.
//   Asserted as above: the rate within 3% and the L2 error below 5%. Measured: -1.8% and 1.4%.
//   (With the pressure pinned at one particle, before 2026-11-27, -4.4% and 4.8%: the pinned
//   particle changed at every re-sort; docs/sph.md, "Incompressible SPH".)
//   Without shifting the projection blows up by t = 0.14 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "app/simulation.hpp"
#include "validation/case_factory.hpp"

namespace partimix {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSpeed = 1.0;
constexpr double kViscosity = 0.01;  // nu [m^2/s], rho = 1000 kg/m^3
constexpr double kDecay = -8.0 * kPi * kPi * kViscosity;
constexpr int kParticlesPerSide = 50;

Vec3 exact_velocity(const Vec3& x, double t) {
  const double amplitude = kSpeed * std::exp(kDecay * t);
  return amplitude * Vec3(-std::cos(2.0 * kPi * x.x()) * std::sin(2.0 * kPi * x.y()),
                          std::sin(2.0 * kPi * x.x()) * std::cos(2.0 * kPi * x.y()), 0.0);
}

double exact_pressure(const Vec3& x) {
  return -1000.0 * kSpeed * kSpeed * (std::cos(4.0 * kPi * x.x()) + std::cos(4.0 * kPi * x.y())) /
         4.0;
}

io::Case taylor_green(const std::string& scheme, const std::string& shifting) {
  io::Case c;
  c.name = "taylor_green";
  sph::SphSection& sph = testing_cases::add_sph(c);
  c.domain.dimensions = 2;
  c.domain.lo = Vec3(0.0, 0.0, 0.0);
  c.domain.hi = Vec3(1.0, 1.0, 0.0);
  c.domain.periodic = {true, true, false};
  sph.config.spacing = 1.0 / kParticlesPerSide;
  sph.config.max_velocity = kSpeed;
  sph.config.equation_of_state = "linear";
  sph.config.shifting.model = shifting;
  sph.config.scheme = scheme;
  sph.fluid.density = 1000.0;
  sph.fluid.rheology.viscosity = 1000.0 * kViscosity;
  sph.fluid.regions.push_back(
      {std::make_shared<geometry::Box>(Vec3(0.0, 0.0, -1.0), Vec3(1.0, 1.0, 1.0))});
  return c;
}

// Velocities and densities (linear EOS, rho = rho0 + p / c0^2) of the vortex at t = 0, then one
// step of 1e-9 s so that the solver's rates belong to them.
void start_vortex(app::Simulation& sim) {
  ParticleStore& store = *sim.methods[0].store;
  const double c0 = sim.methods[0].solver->derived_parameters().at("sound_speed [m/s]");
  std::vector<double>& density = store.find_scalar("density")->values;
  for (std::size_t i = 0; i < store.size(); ++i) {
    store.velocity()[i] = exact_velocity(store.position()[i], 0.0);
    density[i] = 1000.0 + exact_pressure(store.position()[i]) / (c0 * c0);
  }
  sim.methods[0].solver->step(1e-9);
}

struct Decay {
  double rate = 0.0;      // fitted b [1/s]
  double l2_error = 0.0;  // of the velocity at the end, over U e^(b t)
};

Decay run_vortex(const std::string& scheme, const std::string& shifting) {
  app::Simulation sim = app::build_simulation(taylor_green(scheme, shifting));
  start_vortex(sim);
  Solver& solver = *sim.methods[0].solver;
  const ParticleStore& store = solver.particles();
  std::vector<double> times;
  std::vector<double> logs;
  double t = 0.0;
  for (double sample = 0.25; sample <= 2.0 + 1e-9; sample += 0.25) {
    while (t < sample - 1e-12) {
      const double dt = std::min(solver.stable_dt(), sample - t);
      solver.step(dt);
      t += dt;
    }
    double largest = 0.0;
    for (std::size_t i = 0; i < store.size(); ++i)
      largest = std::max(largest, store.velocity()[i].norm());
    times.push_back(t);
    logs.push_back(std::log(largest));
  }
  const auto n = static_cast<double>(times.size());
  double st = 0.0, sl = 0.0, stt = 0.0, stl = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    st += times[k];
    sl += logs[k];
    stt += times[k] * times[k];
    stl += times[k] * logs[k];
  }
  Decay d;
  d.rate = (n * stl - st * sl) / (n * stt - st * st);
  double error2 = 0.0;
  for (std::size_t i = 0; i < store.size(); ++i)
    error2 += (store.velocity()[i] - exact_velocity(store.position()[i], t)).squaredNorm();
  d.l2_error =
      std::sqrt(error2 / static_cast<double>(store.size())) / (kSpeed * std::exp(kDecay * t));
  std::printf(
      "Taylor-Green, %s, shifting %s: decay rate %.4f 1/s (exact %.4f, %+.2f%%), L2 error "
      "at t = 2 s %.4f\n",
      scheme.c_str(), shifting.c_str(), d.rate, kDecay, 100.0 * (d.rate / kDecay - 1.0),
      d.l2_error);
  return d;
}

TEST(TaylorGreen, DecaysAtTheAnalyticalRateWithShifting) {
  const Decay shifted = run_vortex("weakly_compressible", "fickian");
  EXPECT_NEAR(shifted.rate / kDecay, 1.0, 0.03);
  EXPECT_LT(shifted.l2_error, 0.05);
}

TEST(TaylorGreen, DecaysAtTheAnalyticalRateIncompressible) {
  const Decay shifted = run_vortex("incompressible", "fickian");
  EXPECT_NEAR(shifted.rate / kDecay, 1.0, 0.03);
  EXPECT_LT(shifted.l2_error, 0.05);
}

}  // namespace
}  // namespace partimix
