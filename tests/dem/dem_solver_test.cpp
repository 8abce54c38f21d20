// The DEM solver end to end (docs/dem.md): contacts found through the cell grid, walls, history
// kept across sorts by cell, velocity Verlet.
// - A sphere thrown at 1 m/s on a plane rebounds at e: within 1e-3 at dt = t_R/100 (measured
//   -4.5e-4 at e = 0.3, +3.5e-5 at 0.9); at the default 0.2 t_R, about ten steps per contact,
//   within 1% (measured +0.64% and +0.25%).
// - Two spheres meeting head on: momentum conserved to round-off, restitution e within 1e-3.
// - A sphere on an incline (rigid-body theory): it rolls without slip at a = (5/7) g sin(alpha)
//   when mu_s > (2/7) tan(alpha), and slides at a = g (sin(alpha) - mu_s cos(alpha)) otherwise;
//   the distance after 0.2 s within 2e-3 (measured 1.5e-4 rolling, 5e-4 sliding), with the
//   grains re-sorted every step so that the contact history must follow its particle.
// - A grain turning with a rotating drum as one rigid body (no gravity, resting on the wall)
//   stays with it: the wall's velocity at the contact enters the contact velocity with the
//   right sign and size, so the tangential force stays near zero and after a tenth of a
//   revolution the grain's angle about the axis matches the drum's within 1e-4 rad (measured
//   3.9e-6; with the wall velocity's sign flipped it is 0.125 rad off).
// - A superquadric with a = b = c and n1 = n2 = 2 does all of the above as the sphere, to 1e-9.
// - Energy: 125 spheres in a closed box of six planes, e = 1, no friction, no gravity: kinetic
//   plus elastic contact energy after 2000 steps at the default step within 2e-3 of the start
//   (measured -6.7e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <utility>

#include "dem/dem_setups.hpp"
#include "dem/dem_solver.hpp"
#include "geometry/drum_surface.hpp"
#include "geometry/plane_surface.hpp"

namespace partimix::dem {
namespace {

using test::add_plane;
using test::box;

constexpr double kRadius = 0.002;
constexpr double kDensity = 2500.0;

// One species of spheres, or (shape) of superquadrics.
Config one_species(double restitution, double friction,
                   const std::optional<Superquadric>& shape = std::nullopt) {
  Config config;
  config.species = {Species{"grain", kDensity, {1.0e7, 0.3}, shape}};
  config.particle_interactions = {Interaction{restitution, friction, 0.0}};
  config.wall_interactions = {Interaction{restitution, friction, 0.0}};
  return config;
}

// Rebound speed of a sphere thrown at 1 m/s onto the plane y = 0 with steps dt (0: the solver's).
double rebound_speed(double restitution, double dt_fraction_of_rayleigh,
                     const std::optional<Superquadric>& shape = std::nullopt) {
  Config config = one_species(restitution, 0.0, shape);
  add_plane(config, Vec3::Zero(), Vec3::UnitY());
  ParticleStore store;
  DemSolver solver(store, box(0.05), config, Vec3::Zero(),
                   Grains{{Vec3(0.0, 1.001 * kRadius, 0.0)}, {kRadius}, {0}, {}, {}, {}});
  store.velocity()[0] = Vec3(0.0, -1.0, 0.0);
  const double dt = dt_fraction_of_rayleigh > 0.0
                        ? dt_fraction_of_rayleigh * solver.derived_parameters()["rayleigh_time [s]"]
                        : solver.stable_dt();
  while (store.velocity()[0].y() < 0.0 || store.position()[0].y() < kRadius)
    solver.step(dt);
  return store.velocity()[0].y();
}

TEST(DemSolver, SphereOnPlaneReboundsAtTheRestitution) {
  for (const double e : {0.3, 0.9}) {
    EXPECT_NEAR(rebound_speed(e, 0.01), e, 1e-3) << "e = " << e;
    EXPECT_NEAR(rebound_speed(e, 0.0), e, 0.01 * e) << "e = " << e << " at the default step";
  }
}

constexpr double kRestitution = 0.6;

// Two grains meeting head on at 1 m/s: their momentum and rebound speed after the contact.
std::pair<Vec3, double> head_on(const std::optional<Superquadric>& shape = std::nullopt) {
  ParticleStore store;
  DemSolver solver(store, box(0.05), one_species(kRestitution, 0.3, shape), Vec3::Zero(),
                   Grains{{Vec3(-1.01 * kRadius, 0.0, 0.0), Vec3(1.01 * kRadius, 0.0, 0.0)},
                          {kRadius, kRadius},
                          {0, 0},
                          {},
                          {},
                          {}});
  const std::size_t left = store.id()[0] == 0 ? 0 : 1;
  store.velocity()[left] = Vec3(0.5, 0.0, 0.0);
  store.velocity()[1 - left] = Vec3(-0.5, 0.0, 0.0);
  const double dt = 0.01 * solver.derived_parameters()["rayleigh_time [s]"];
  for (int n = 0; n < 20000; ++n)
    solver.step(dt);
  return {store.velocity()[0] + store.velocity()[1],
          store.velocity()[1 - left].x() - store.velocity()[left].x()};
}

TEST(DemSolver, HeadOnPairConservesMomentumAndReboundsAtTheRestitution) {
  const auto [momentum, rebound] = head_on();
  EXPECT_LT(momentum.norm(), 1e-12);
  EXPECT_NEAR(rebound, kRestitution, 1e-3);
}

// Distance along the incline after `duration` from rest, gravity tilted by alpha.
double incline_distance(double alpha, double friction, double duration,
                        const std::optional<Superquadric>& shape = std::nullopt) {
  Config config = one_species(0.3, friction, shape);
  config.sort_interval = 1;
  add_plane(config, Vec3::Zero(), Vec3::UnitY());
  const double g = 9.81;
  const Vec3 gravity(g * std::sin(alpha), -g * std::cos(alpha), 0.0);
  ParticleStore store;
  Domain domain = box(0.05);
  domain.periodic = {true, false, false};
  const double mass = kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  const double rest = std::pow(
      mass * g * std::cos(alpha) / (4.0 / 3.0 * 1.0e7 / 0.91 * std::sqrt(kRadius)), 2.0 / 3.0);
  DemSolver solver(store, domain, config, gravity,
                   Grains{{Vec3(0.0, kRadius - rest, 0.0)}, {kRadius}, {0}, {}, {}, {}});
  double travelled = 0.0;
  const double dt = solver.stable_dt();
  for (double t = 0.0; t < duration; t += dt) {
    solver.step(dt);
    travelled += store.velocity()[0].x() * dt;
  }
  return travelled;
}

TEST(DemSolver, SphereRollsOrSlidesDownAnInclineAsTheRigidBodyTheorySays) {
  const double alpha = 30.0 * std::numbers::pi / 180.0;
  const double duration = 0.2;
  const double g = 9.81;
  const double rolling = 0.5 * (5.0 / 7.0) * g * std::sin(alpha) * duration * duration;
  EXPECT_NEAR(incline_distance(alpha, 0.5, duration), rolling, 2e-3 * rolling);
  const double friction = 0.1;  // < (2/7) tan 30 deg = 0.165
  const double sliding =
      0.5 * g * (std::sin(alpha) - friction * std::cos(alpha)) * duration * duration;
  EXPECT_NEAR(incline_distance(alpha, friction, duration), sliding, 2e-3 * sliding);
}

// A superquadric with a = b = c and n1 = n2 = 2 is the sphere: the midway point, the wall's
// support point and the rotor of three equal moments give the spheres' results to the Newton
// tolerance (rebound on a plane, a head-on pair, rolling and sliding down an incline).
TEST(DemSolver, SphereShapedSuperquadricsMoveAsTheSpheres) {
  const Superquadric sphere(Vec3::Constant(kRadius), 2.0, 2.0);
  for (const double e : {0.3, 0.9})
    EXPECT_NEAR(rebound_speed(e, 0.01, sphere), rebound_speed(e, 0.01), 1e-9) << "e = " << e;
  const auto [momentum, rebound] = head_on(sphere);
  EXPECT_LT(momentum.norm(), 1e-12);
  EXPECT_NEAR(rebound, head_on().second, 1e-9);
  const double alpha = 30.0 * std::numbers::pi / 180.0;
  for (const double friction : {0.5, 0.1}) {
    const double expected = incline_distance(alpha, friction, 0.2);
    EXPECT_NEAR(incline_distance(alpha, friction, 0.2, sphere), expected, 1e-9 * expected)
        << "friction " << friction;
  }
}

TEST(DemSolver, GrainCoRotatingWithTheDrumStaysWithIt) {
  Config config = one_species(0.5, 0.85);
  geometry::MotionConfig motion;
  motion.type = "rotation";
  motion.rpm = 30.0;
  const double drum_radius = 0.1;
  config.walls.push_back(
      {std::make_shared<geometry::DrumSurface>(Vec3::Zero(), Vec3::UnitZ(), drum_radius),
       motion,
       {1.0e7, 0.3},
       {}});
  Domain domain = box(0.11);
  domain.periodic = {false, false, true};
  ParticleStore store;
  const double centre = drum_radius - kRadius;
  DemSolver solver(store, domain, config, Vec3::Zero(),
                   Grains{{Vec3(0.0, -centre, 0.0)}, {kRadius}, {0}, {}, {}, {}});
  const double omega = 30.0 * 2.0 * std::numbers::pi / 60.0;
  store.velocity()[0] = Vec3(omega * centre, 0.0, 0.0);
  store.find_vector("angular_velocity")->values[0] = omega * Vec3::UnitZ();
  const double duration = 0.2;  // a tenth of a revolution
  const double dt = solver.stable_dt();
  int steps = 0;
  for (; steps * dt < duration; ++steps)
    solver.step(dt);
  const Vec3& x = store.position()[0];
  const double turned = std::atan2(x.y(), x.x()) + 0.5 * std::numbers::pi;
  EXPECT_NEAR(turned, omega * steps * dt, 1e-4);
}

TEST(DemSolver, ElasticFrictionlessGasInABoxKeepsItsEnergy) {
  Config config = one_species(1.0, 0.0);
  const double half = 0.02;
  for (int axis = 0; axis < 3; ++axis) {
    add_plane(config, -half * Vec3::Unit(axis), Vec3::Unit(axis));
    add_plane(config, half * Vec3::Unit(axis), -Vec3::Unit(axis));
  }
  Grains grains;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b)
      for (int c = 0; c < 5; ++c) {
        grains.position.push_back(Vec3(a - 2, b - 2, c - 2) * 3.0 * kRadius);
        grains.radius.push_back(kRadius);
        grains.species.push_back(0);
      }
  ParticleStore store;
  DemSolver solver(store, box(1.1 * half), config, Vec3::Zero(), grains);
  for (auto& v : store.velocity())
    v = Vec3(speed(random), speed(random), speed(random));
  // Kinetic energy and the elastic energy (2/5) k_H d^(5/2) of every contact (Hertz).
  const double grain_modulus = 1.0e7 / (2.0 * 0.91);
  const double wall_modulus = 1.0 / (0.91 / 1.0e7 + 0.91 / 2.0e11);
  auto elastic = [](double modulus, double radius, double overlap) {
    return overlap > 0.0 ? 0.4 * 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(overlap, 2.5)
                         : 0.0;
  };
  auto energy = [&] {
    double sum = 0.0;
    const auto& x = store.position();
    for (std::size_t i = 0; i < store.size(); ++i) {
      sum += 0.5 * store.mass()[i] * store.velocity()[i].squaredNorm();
      for (std::size_t j = i + 1; j < store.size(); ++j)
        sum += elastic(grain_modulus, 0.5 * kRadius, 2.0 * kRadius - (x[i] - x[j]).norm());
      for (int axis = 0; axis < 3; ++axis) {
        sum += elastic(wall_modulus, kRadius, kRadius - (half + x[i][axis]));
        sum += elastic(wall_modulus, kRadius, kRadius - (half - x[i][axis]));
      }
    }
    return sum;
  };
  const double start = energy();
  for (int n = 0; n < 2000; ++n)
    solver.step(solver.stable_dt());
  EXPECT_NEAR(energy() / start, 1.0, 2e-3);
}

}  // namespace
}  // namespace partimix::dem
