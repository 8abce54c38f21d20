// The acceleration that MovingBodies gives each wall particle (field "body_acceleration", used
// by the wall pressure, docs/sph.md "Walls") against the second derivative of the closed-form
// planetary path x = e (cos theta_G, sin theta_G) + d (cos theta_R, sin theta_R) (docs/motions.md):
// a = -e omega_G^2 (cos theta_G, sin theta_G) - d omega_R^2 (cos theta_R, sin theta_R).
// Tolerance 1e-6 of |a|: the central difference over +-1e-6 s is exact to O(1e-12 omega^2)
// and its round-off is about 1e-9 m/s^2 here.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/moving_bodies.hpp"

namespace partimix::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(MovingBodies, PlanetaryParticleAccelerationIsTheSecondDerivativeOfItsPath) {
  const double e = 0.17 * 0.1386;
  const double d = 0.0299;
  ParticleStore store;
  store.resize(1);
  store.position()[0] = Vec3(e + d, 0.0, 0.1);
  store.kind()[0] = static_cast<std::int32_t>(ParticleKind::wall);
  Domain domain;
  domain.lo = Vec3::Constant(-1.0);
  domain.hi = Vec3::Constant(1.0);
  MovingBodies bodies(store, domain);
  MotionConfig config;
  config.type = "planetary";
  config.axis_point = Vec3(e, 0.0, 0.0);
  config.revolution_rpm = -25.0;
  config.rpm = 60.0;
  bodies.add_body(0, motion_registry().create("planetary", config));
  const double omega_g = -25.0 * 2.0 * kPi / 60.0;
  const double omega_r = 60.0 * 2.0 * kPi / 60.0;
  for (double t : {0.1, 0.77, 2.4, 3.9}) {
    bodies.move_to(t);
    const Vec3 expected =
        -e * omega_g * omega_g * Vec3(std::cos(omega_g * t), std::sin(omega_g * t), 0.0) -
        d * omega_r * omega_r * Vec3(std::cos(omega_r * t), std::sin(omega_r * t), 0.0);
    const Vec3& acceleration = store.find_vector("body_acceleration")->values[0];
    EXPECT_LT((acceleration - expected).norm(), 1e-6 * expected.norm()) << "at t = " << t;
  }
}

}  // namespace
}  // namespace partimix::geometry
