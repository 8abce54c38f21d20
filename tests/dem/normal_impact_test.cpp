// Normal impact of a sphere on a wall and of two equal spheres (docs/dem.md, "Normal force"),
// the relative motion m* d'' = -F_n(d, d') integrated by velocity Verlet at 1/4000 of the
// contact time, from first touch to separation (overlap back to zero):
// - elastic Hertz (e = 1): maximum overlap (15 m* v^2 / (16 E* sqrt(R*)))^(2/5) and contact
//   time 2.868 (m*^2 / (R* E*^2 v))^(1/5) (Johnson 1985, section 11.4), within 1e-3 (the
//   constant 2.868 is given to four digits);
// - damped Hertz: the rebound speed is e times the impact speed, the same at 0.1, 1 and 10 m/s
//   (Antypov and Elliott 2011), within 1e-3;
// - linear spring-dashpot: restitution e and contact time pi / sqrt(k/m* (1 - beta^2)), 1e-3.
// The tolerance covers the time step (second order: the error at dt = t_c/4000 is about 1e-6)
// and the end of contact found to within one step.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "dem/normal_contact.hpp"
#include "dem/pair_properties.hpp"

namespace partimix::dem {
namespace {

constexpr double kRadius = 0.002;    // [m], the seed's grains
constexpr double kDensity = 2500.0;  // [kg/m^3]
constexpr double kInfinity = std::numeric_limits<double>::infinity();
const Material kGrain{1.0e7, 0.3};  // E [Pa], nu
const Material kSteel{2.0e11, 0.3};

double sphere_mass() {
  return 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity;
}

ContactSide grain() {
  return {kGrain, kRadius, sphere_mass()};
}

ContactSide wall() {
  return {kSteel, kInfinity, kInfinity};
}

struct Impact {
  double largest_overlap = 0.0;  // [m]
  double duration = 0.0;         // [s]
  double rebound_speed = 0.0;    // [m/s]
};

// The pair meets at speed `speed`; step dt until the overlap is back to zero.
Impact collide(const NormalContactLaw& law, const PairProperties& pair, double speed, double dt) {
  double overlap = 0.0;
  double rate = speed;  // d(overlap)/dt = -u_n
  double accel = 0.0;
  Impact impact;
  double time = 0.0;
  do {
    rate += 0.5 * dt * accel;
    overlap += dt * rate;
    accel = -law.respond(pair, std::max(overlap, 0.0), -rate).force / pair.mass;
    rate += 0.5 * dt * accel;
    time += dt;
    impact.largest_overlap = std::max(impact.largest_overlap, overlap);
  } while (overlap > 0.0);
  // The step that left the contact: back to where the overlap crossed zero.
  impact.duration = time - overlap / rate;
  impact.rebound_speed = -rate;
  return impact;
}

double hertz_overlap(const PairProperties& p, double v) {
  return std::pow(15.0 * p.mass * v * v / (16.0 * p.youngs_modulus * std::sqrt(p.radius)), 0.4);
}

double hertz_duration(const PairProperties& p, double v) {
  return 2.868 *
         std::pow(p.mass * p.mass / (p.radius * p.youngs_modulus * p.youngs_modulus * v), 0.2);
}

std::unique_ptr<NormalContactLaw> hertz() {
  return normal_contact_registry().create("hertz", {});
}

TEST(NormalImpact, ElasticHertzOverlapAndDurationOnAWallAndBetweenSpheres) {
  for (const ContactSide& other : {wall(), grain()}) {
    const PairProperties pair = pair_properties(grain(), other, 1.0);
    const double speed = 1.0;
    const double t_c = hertz_duration(pair, speed);
    const Impact impact = collide(*hertz(), pair, speed, t_c / 4000.0);
    EXPECT_NEAR(impact.largest_overlap / hertz_overlap(pair, speed), 1.0, 1e-3);
    EXPECT_NEAR(impact.duration / t_c, 1.0, 1e-3);
    EXPECT_NEAR(impact.rebound_speed / speed, 1.0, 1e-3);
  }
}

TEST(NormalImpact, DampedHertzReboundsAtEWhateverTheSpeed) {
  for (const double e : {0.3, 0.6, 0.9}) {
    for (const ContactSide& other : {wall(), grain()}) {
      const PairProperties pair = pair_properties(grain(), other, e);
      for (const double speed : {0.1, 1.0, 10.0}) {
        const Impact impact = collide(*hertz(), pair, speed, hertz_duration(pair, speed) / 4000.0);
        EXPECT_NEAR(impact.rebound_speed / speed, e, 1e-3) << "speed " << speed;
      }
    }
  }
}

TEST(NormalImpact, LinearSpringDashpotReboundsAtEAfterItsHalfPeriod) {
  const double stiffness = 1.0e4;  // [N/m]
  const auto law = normal_contact_registry().create("linear", {stiffness});
  for (const double e : {0.5, 0.9}) {
    const PairProperties pair = pair_properties(grain(), grain(), e);
    const double beta = pair.damping;
    const double t_c = std::numbers::pi / std::sqrt(stiffness / pair.mass * (1.0 - beta * beta));
    const Impact impact = collide(*law, pair, 1.0, t_c / 4000.0);
    EXPECT_NEAR(impact.rebound_speed, e, 1e-3);
    EXPECT_NEAR(impact.duration / t_c, 1.0, 1e-3);
  }
}

TEST(PairProperties, WallIsInfinitelyLargeAndHeavy) {
  const PairProperties on_wall = pair_properties(grain(), wall(), 0.5);
  EXPECT_DOUBLE_EQ(on_wall.radius, kRadius);
  EXPECT_DOUBLE_EQ(on_wall.mass, sphere_mass());
  const PairProperties spheres = pair_properties(grain(), grain(), 0.5);
  EXPECT_DOUBLE_EQ(spheres.radius, 0.5 * kRadius);
  EXPECT_DOUBLE_EQ(spheres.youngs_modulus, kGrain.youngs_modulus / (2.0 * (1.0 - 0.09)));
  EXPECT_DOUBLE_EQ(damping_factor(1.0), 0.0);
}

}  // namespace
}  // namespace partimix::dem
