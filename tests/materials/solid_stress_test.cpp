// The solid's stress rate and artificial stress (docs/multi-material-sph.md, "Solid"): the
// Jaumann rate turns a stress with a rigid rotation (S(t) = Q(t) S0 Q(t)^T, its invariants
// kept) and gives 2 G times the deviatoric strain rate otherwise; the artificial stress is
// -epsilon sigma'_aa / rho^2 on the tensile principal stresses only, in any frame.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "materials/artificial_stress.hpp"
#include "materials/jaumann_rate.hpp"

namespace partimix::materials {
namespace {

Mat3 rotation_about(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A quarter turn at omega = 2 rad/s about (1, 2, 3) with no strain, integrated by classical
// Runge-Kutta in 1,000 steps: S matches Q S0 Q^T within 1e-9 of |S0| (the scheme's error is
// about (omega dt)^4 ~ 1e-11) and its second invariant is kept to the same.
TEST(JaumannRate, RigidRotationTurnsTheStress) {
  const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized();
  const double omega = 2.0;
  Mat3 spin_tensor;  // L = [omega]_x, v = omega x x
  spin_tensor << 0.0, -axis[2], axis[1], axis[2], 0.0, -axis[0], -axis[1], axis[0], 0.0;
  const Mat3 l = omega * spin_tensor;
  Mat3 s0;
  s0 << 3.0, 1.0, -0.5, 1.0, -1.0, 2.0, -0.5, 2.0, -2.0;  // traceless, symmetric [MPa]
  const double end = 0.5 * std::numbers::pi / omega;      // a quarter turn
  const int steps = 1000;
  const double dt = end / steps;
  const double g = 1e3;
  Mat3 s = s0;
  for (int k = 0; k < steps; ++k) {
    const Mat3 k1 = jaumann_stress_rate(s, l, g);
    const Mat3 k2 = jaumann_stress_rate(s + 0.5 * dt * k1, l, g);
    const Mat3 k3 = jaumann_stress_rate(s + 0.5 * dt * k2, l, g);
    const Mat3 k4 = jaumann_stress_rate(s + dt * k3, l, g);
    s += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  const Mat3 q = rotation_about(axis, omega * end);
  const Mat3 expected = q * s0 * q.transpose();
  EXPECT_LT((s - expected).norm(), 1e-9 * s0.norm());
  EXPECT_NEAR(s.squaredNorm(), s0.squaredNorm(), 1e-9 * s0.squaredNorm());
  EXPECT_NEAR(s.trace(), 0.0, 1e-12 * s0.norm());
}

// With no stress, a pure strain rate gives 2 G (D - tr D / 3 I); a volumetric one gives none.
TEST(JaumannRate, StrainRateGivesTwiceTheShearModulusTimesItsDeviator) {
  Mat3 l;
  l << 1.0, 0.5, 0.0, 0.5, -0.25, 0.0, 0.0, 0.0, 0.75;  // symmetric: no spin
  const double g = 2.0e6;
  const Mat3 expected = 2.0 * g * (l - l.trace() / 3.0 * Mat3::Identity());
  EXPECT_LT((jaumann_stress_rate(Mat3::Zero(), l, g) - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT(jaumann_stress_rate(Mat3::Zero(), 0.3 * Mat3::Identity(), g).norm(), 1e-9);
}

// sigma = diag(2, -1, 0.5) MPa: R = diag(-eps 2e6, 0, -eps 0.5e6) / rho^2, and in a rotated
// frame the rotated R, within 1e-12 relative; a compressive stress has none.
TEST(ArtificialStress, ActsOnTheTensilePrincipalStressesInAnyFrame) {
  const double rho = 1200.0;
  const double epsilon = 0.3;
  const Mat3 sigma = Vec3(2.0e6, -1.0e6, 0.5e6).asDiagonal();
  const Mat3 expected =
      Vec3(-epsilon * 2.0e6, 0.0, -epsilon * 0.5e6).asDiagonal() * (1.0 / (rho * rho));
  EXPECT_LT((artificial_stress(sigma, rho, epsilon) - expected).norm(), 1e-12 * expected.norm());
  const Mat3 q = rotation_about(Vec3(0.3, -1.0, 0.7), 0.9);
  const Mat3 rotated = artificial_stress(q * sigma * q.transpose(), rho, epsilon);
  EXPECT_LT((rotated - q * expected * q.transpose()).norm(), 1e-12 * expected.norm());
  const Mat3 compressive = Vec3(-2.0e6, -1.0e6, -0.5e6).asDiagonal();
  EXPECT_EQ(artificial_stress(q * compressive * q.transpose(), rho, epsilon).norm(), 0.0);
}

}  // namespace
}  // namespace partimix::materials
