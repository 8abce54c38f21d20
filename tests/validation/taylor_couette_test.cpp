// Circular Couette flow of a power-law fluid in 2D: the inner cylinder (radius R1) turns at
// Omega, the outer (R2) is at rest, no gravity. At steady state the torque balance gives the
// shear stress tau_r_theta = C / r^2, so the shear rate gamma_dot = -r d(omega)/dr = (C / (K
// r^2))^(1/n) varies across the gap and, for n != 1, so does the viscosity. Integrating with
// omega(R1) = Omega and omega(R2) = 0 (Bird, Armstrong and Hassager 1987, example 4.2-5):
//   omega(r) = Omega (r^(-2/n) - R2^(-2/n)) / (R1^(-2/n) - R2^(-2/n))
//   C = K (2 Omega / (n (R1^(-2/n) - R2^(-2/n))))^n,   torque per length = 2 pi C.
// The viscosity varies with r here, so the Morris term alone, which approximates
// div(eta grad v), misses the part div(eta (grad v)^T) = -eta'(r) v / r e_theta of the viscous
// stress; the stress-form operator (docs/sph.md, "Viscous operators") includes it.
// The inner cylinder is a body in rotation (geometry/rotation_motion.hpp): its wall particles
// turn with it. Fluid: the seed's CMC (K = 13.9 Pa s^n, n = 0.47); R1 = 5 mm, R2 = 10 mm, Omega = 2
// rad/s, gap / dp = 10 on concentric rings (a polar lattice, so that both walls are smooth); steady
// after 0.01 s (gap / dp = 10: L2 and stress unchanged to 1e-4 when run to 0.02 s).
// Tolerances: L2 deviation of v_theta within 2% of Omega R1 (measured 1.36%, 0.96% at gap / dp
// = 10, 14), and the mean of eta_a gamma_dot r^2 over particles more than 2h from both walls
// within 3% of C (measured -0.02%, -0.48%). The Morris form alone stays at 3.6-3.9% L2 and
// +7.2-7.4% stress at gap / dp = 10, 14, 20; the test checks it is at least twice as far off.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sph/wcsph_solver.hpp"

namespace partimix {
namespace {

constexpr double kInner = 0.005;
constexpr double kOuter = 0.01;
constexpr double kOmega = 2.0;
constexpr double kConsistency = 13.9;
constexpr double kIndex = 0.47;
constexpr int kRings = 10;
constexpr double kSpacing = (kOuter - kInner) / kRings;

double power_of_radius(double r) {
  return std::pow(r, -2.0 / kIndex);
}

double exact_angular_velocity(double r) {
  return kOmega * (power_of_radius(r) - power_of_radius(kOuter)) /
         (power_of_radius(kInner) - power_of_radius(kOuter));
}

double exact_stress_constant() {
  return kConsistency *
         std::pow(2.0 * kOmega / (kIndex * (power_of_radius(kInner) - power_of_radius(kOuter))),
                  kIndex);
}

// `count` rings of particles spaced kSpacing, the first at radius `first`, going outward
// (step +1) or inward (step -1); each ring holds round(2 pi r / dp) particles.
void add_rings(ParticleStore& store, double first, int count, int step, ParticleKind kind) {
  for (int k = 0; k < count; ++k) {
    const double r = first + step * k * kSpacing;
    const int n = static_cast<int>(std::lround(2.0 * std::numbers::pi * r / kSpacing));
    const double offset = 0.5 * (k % 2);
    for (int a = 0; a < n; ++a) {
      const double angle = 2.0 * std::numbers::pi * (a + offset) / n;
      const std::size_t i = store.size();
      store.resize(i + 1);
      store.position()[i] = Vec3(r * std::cos(angle), r * std::sin(angle), 0.0);
      store.kind()[i] = static_cast<std::int32_t>(kind);
      store.id()[i] = static_cast<std::int64_t>(i);
    }
  }
}

struct Measured {
  double l2 = 0.0;            // of v_theta, relative to Omega R1
  double stress_error = 0.0;  // mean eta gamma_dot r^2 away from the walls, relative to C
};

Measured run(const std::string& viscous_operator) {
  ParticleStore store;
  add_rings(store, kInner + 0.5 * kSpacing, kRings, 1, ParticleKind::fluid);
  Domain domain;
  domain.dimensions = 2;
  domain.lo = Vec3(-1.5 * kOuter, -1.5 * kOuter, 0.0);
  domain.hi = Vec3(1.5 * kOuter, 1.5 * kOuter, 0.0);
  geometry::MovingBodies bodies(store, domain);
  std::size_t first = store.size();
  add_rings(store, kInner - 0.5 * kSpacing, 3, -1, ParticleKind::wall);
  geometry::MotionConfig rotation;
  rotation.type = "rotation";
  rotation.rpm = kOmega * 60.0 / (2.0 * std::numbers::pi);
  bodies.add_body(first, geometry::motion_registry().create("rotation", rotation));
  first = store.size();
  add_rings(store, kOuter + 0.5 * kSpacing, 3, 1, ParticleKind::wall);
  bodies.add_body(first, geometry::motion_registry().create("fixed", {}));
  sph::Config config;
  config.spacing = kSpacing;
  config.max_velocity = kOmega * kInner;
  config.viscous_operator = viscous_operator;
  sph::FluidProperties fluid;
  fluid.rheology.model = "power_law";
  fluid.rheology.consistency = kConsistency;
  fluid.rheology.flow_index = kIndex;
  fluid.rheology.viscosity_min = 0.1;
  fluid.rheology.viscosity_max = 1000.0;
  sph::WcsphSolver solver(store, domain, config, fluid, Vec3::Zero(), &bodies);
  const double end_time = 0.01;
  for (double t = 0.0; t < end_time;) {
    const double dt = std::min(solver.stable_dt(), end_time - t);
    solver.step(dt);
    t += dt;
  }
  const auto& rate = store.find_scalar("shear_rate")->values;
  const auto& viscosity = store.find_scalar("viscosity")->values;
  const double reach = 2.0 * config.smoothing_length();
  Measured m;
  int count = 0;
  int interior = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    const Vec3& x = store.position()[i];
    const double r = x.norm();
    const Vec3 tangent(-x.y() / r, x.x() / r, 0.0);
    const double error = store.velocity()[i].dot(tangent) - r * exact_angular_velocity(r);
    m.l2 += error * error;
    ++count;
    if (r > kInner + reach && r < kOuter - reach) {
      m.stress_error += viscosity[i] * rate[i] * r * r;
      ++interior;
    }
  }
  m.l2 = std::sqrt(m.l2 / count) / (kOmega * kInner);
  m.stress_error = m.stress_error / interior / exact_stress_constant() - 1.0;
  std::printf("Taylor-Couette (%s): L2 of v_theta %.4f of Omega R1, stress constant %+.4f\n",
              viscous_operator.c_str(), m.l2, m.stress_error);
  return m;
}

TEST(TaylorCouette, PowerLawProfileAndStressWithTheStressForm) {
  const Measured stress_form = run("stress");
  EXPECT_LT(stress_form.l2, 0.02);
  EXPECT_NEAR(stress_form.stress_error, 0.0, 0.03);
  const Measured morris = run("morris");
  EXPECT_GT(morris.l2, 2.0 * stress_form.l2) << "the transposed part should matter here";
}

}  // namespace
}  // namespace partimix
