// Tangential damping (docs/dem.md, "Tangential force"): a sphere resting on a plane under
// gravity, with the linear law (k_t = (2/7) k_n, constant) and friction too large to slide, is
// given a small tangential speed v_0. The contact point then moves as a damped oscillator:
// its tangential velocity u = v_x + l w_z (l = R - d/2 the lever) obeys
//   m_eff u' = F_t = -k_t xi - c_t u,   1/m_eff = 1/m + l^2/I,   c_t = 2 sqrt(5/6) beta sqrt(k_t m)
// (m* = m against a wall), so with w_n = sqrt(k_t/m_eff), zeta = c_t / (2 sqrt(k_t m_eff)) and
// w_d = w_n sqrt(1 - zeta^2),
//   u(t) = v_0 exp(-zeta w_n t) (cos w_d t - zeta/sqrt(1 - zeta^2) sin w_d t),
// and the centre's speed is v_x(t) = v_0 + (m_eff/m)(u(t) - v_0) (the friction impulse over m).
// At e = 0.8 (beta = 0.071, zeta = 0.121: the contact-point mass is m/3.5, hence sqrt 3.5 in
// zeta) the test asserts v_x(t) over three periods within 1e-3 v_0 at 1000 steps per period
// (measured 3.4e-4: the damping takes the half-step velocity, an error of first order in dt; at
// e = 1 the error is 8e-6). Compared with the undamped curve the same run is off by 0.26 v_0,
// so a c_t left out, or of the wrong size, fails.
// Both laws give c_t = 2 sqrt(5/6) beta sqrt(k_t m*) to round-off (Hertz-Mindlin forms it from
// the normal damping times sqrt(4 G* / E*)), for two different materials.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "dem/normal_contact.hpp"
#include "dem/sphere_on_plane.hpp"

namespace partimix::dem {
namespace {

constexpr double kRadius = 0.002;
constexpr double kDensity = 2500.0;
constexpr double kNormalStiffness = 1.0e4;  // N/m
constexpr double kSpeed = 1.0e-4;           // v_0 [m/s]
constexpr double kGravity = 9.81;
constexpr double kStepsPerPeriod = 1000;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Oscillator {
  double natural;        // w_n
  double damping_ratio;  // zeta
  double mass_ratio;     // m_eff / m
};

// The largest |v_x - v_x,theory| over three periods, relative to v_0, at restitution e.
double worst_speed_error(double restitution, Oscillator& theory) {
  const auto law = normal_contact_registry().create("linear", {kNormalStiffness});
  const auto no_rolling = rolling_resistance_registry().create("none", {});
  testing::SphereOnPlane s;
  s.normal_law = law.get();
  s.rolling = no_rolling.get();
  s.radius = kRadius;
  s.mass = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3) * kDensity;
  s.pair = pair_properties({{1.0e7, 0.3}, kRadius, s.mass}, {{1.0e7, 0.3}, kInfinity, kInfinity},
                           restitution);
  s.friction = 1.0e6;
  s.gravity = Vec3(0.0, -kGravity, 0.0);
  const double overlap = s.mass * kGravity / kNormalStiffness;  // at rest on the plane
  s.position = Vec3(0.0, kRadius - overlap, 0.0);
  s.velocity = Vec3(kSpeed, 0.0, 0.0);

  const double lever = kRadius - 0.5 * overlap;
  const double stiffness = law->respond(s.pair, overlap, 0.0).tangential_stiffness;
  const double m_eff = 1.0 / (1.0 / s.mass + lever * lever / s.inertia());
  const double c_t = 2.0 * std::sqrt(5.0 / 6.0) * s.pair.damping * std::sqrt(stiffness * s.mass);
  theory = {std::sqrt(stiffness / m_eff), c_t / (2.0 * std::sqrt(stiffness * m_eff)),
            m_eff / s.mass};
  const double zeta = theory.damping_ratio;
  const double damped = theory.natural * std::sqrt(1.0 - zeta * zeta);
  const double period = 2.0 * std::numbers::pi / damped;
  const double dt = period / kStepsPerPeriod;
  s.compute_loads(0.0);  // the loads at t = 0, the spring not yet stretched
  double worst = 0.0;
  for (int k = 1; k <= 3 * static_cast<int>(kStepsPerPeriod); ++k) {
    s.step(dt);
    const double t = k * dt;
    const double u =
        kSpeed * std::exp(-zeta * theory.natural * t) *
        (std::cos(damped * t) - zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(damped * t));
    const double expected = kSpeed + theory.mass_ratio * (u - kSpeed);
    worst = std::max(worst, std::abs(s.velocity.x() - expected) / kSpeed);
  }
  return worst;
}

TEST(TangentialDamping, StickingContactRingsDownAtTheDampingRatio) {
  Oscillator theory{};
  EXPECT_LT(worst_speed_error(0.8, theory), 1e-3);
  EXPECT_NEAR(theory.mass_ratio, 2.0 / 7.0, 1e-3);
  EXPECT_NEAR(theory.damping_ratio, 0.121, 1e-3);
}

TEST(TangentialDamping, ElasticContactRingsWithoutDecay) {
  Oscillator theory{};
  EXPECT_LT(worst_speed_error(1.0, theory), 1e-3);
  EXPECT_EQ(theory.damping_ratio, 0.0);
}

TEST(TangentialDamping, BothLawsGiveTheCoefficientOfTheirTangentialStiffness) {
  const PairProperties pair =
      pair_properties({{7.0e9, 0.25}, 0.002, 1.0e-4}, {{2.0e8, 0.45}, 0.003, 3.0e-4}, 0.6);
  for (const char* name : {"hertz", "linear"}) {
    const auto law = normal_contact_registry().create(name, {kNormalStiffness});
    const NormalResponse response = law->respond(pair, 1.0e-5, -0.1);
    const double expected = 2.0 * std::sqrt(5.0 / 6.0) * pair.damping *
                            std::sqrt(response.tangential_stiffness * pair.mass);
    EXPECT_GT(expected, 0.0) << name;
    EXPECT_NEAR(response.tangential_damping, expected, 1e-14 * expected) << name;
  }
}

}  // namespace
}  // namespace partimix::dem
