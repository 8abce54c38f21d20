// The rotation of a rigid grain with three principal moments, dem/rigid_rotation.hpp
// (docs/dem.md, "Superquadric grains", Rotation). A torque-free asymmetric top I = (1, 2, 3):
// started near the intermediate axis it tumbles (the Dzhanibekov flips), near the largest axis
// it wobbles. The world momentum L is the state and no torque acts, so it must not change at
// all; the energy error stays within a bound that falls as dt^2 (ratio 3.5 to 4.5 when dt
// halves) and does not drift; the orientation and the body angular velocity converge at second
// order to a fine-step RK4 reference of Euler's equations with the quaternion kinematics. For
// I1 = I2 = I3 the drift is the spheres' rule to 1e-14, a symmetric top is turned exactly, a
// constant torque from rest gives omega = T t / I, and the drift run back returns the start.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "dem/rigid_rotation.hpp"

namespace partimix::dem {
namespace {

const Vec3 kTop(1.0, 2.0, 3.0);
const Vec3 kTumbling(0.04, 2.0, 0.04);  // body momentum near the intermediate axis
const Vec3 kWobbling(0.6, 0.4, 2.0);    // near the largest moment's axis
// max |E - E0| / E0 < kEnergyBound dt^2 (measured 0.0087 tumbling, 0.0099 wobbling).
constexpr double kEnergyBound = 0.012;

Quaternion start_orientation() {
  return Quaternion(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()));
}

// The angle of the rotation that takes a to b.
double angle_between(const Quaternion& a, const Quaternion& b) {
  return 2.0 * std::asin(std::min(1.0, (a.conjugate() * b).vec().norm()));
}

struct EnergyRun {
  double first_half = 0.0;  // max |E - E0| / E0 over the first half of the run
  double second_half = 0.0;
  int flips = 0;  // sign changes of the body momentum on the intermediate axis
  bool momentum_kept = true;
  double norm_error = 0.0;  // max ||q| - 1|
};

// Kick-drift-kick with zero torque from body momentum `body` over `duration`.
EnergyRun run_free(const Vec3& body, double dt, double duration) {
  const RigidRotor top(kTop);
  Quaternion q = start_orientation();
  const Vec3 start = q * body;
  Vec3 momentum = start;
  const double energy = top.kinetic_energy(q, momentum);
  const int steps = static_cast<int>(std::lround(duration / dt));
  EnergyRun run;
  double last = body.y();
  for (int n = 1; n <= steps; ++n) {
    kick_angular_momentum(momentum, Vec3::Zero(), dt);
    top.drift(q, momentum, dt);
    kick_angular_momentum(momentum, Vec3::Zero(), dt);
    const double error = std::abs(top.kinetic_energy(q, momentum) / energy - 1.0);
    double& half = 2 * n <= steps ? run.first_half : run.second_half;
    half = std::max(half, error);
    const double middle = (q.conjugate() * momentum).y();
    run.flips += middle * last < 0.0 ? 1 : 0;
    last = middle;
    run.momentum_kept = run.momentum_kept && momentum == start;
    run.norm_error = std::max(run.norm_error, std::abs(q.norm() - 1.0));
  }
  return run;
}

TEST(RigidRotation, TumblingTopKeepsMomentumAndEnergyWithoutDrift) {
  const double dt = 0.01;
  const EnergyRun run = run_free(kTumbling, dt, 400.0);
  EXPECT_GE(run.flips, 10);
  EXPECT_TRUE(run.momentum_kept);
  EXPECT_LT(run.norm_error, 1e-14);
  const double error = std::max(run.first_half, run.second_half);
  EXPECT_LT(error, kEnergyBound * dt * dt);
  EXPECT_LT(run.second_half, 1.05 * run.first_half);
  RecordProperty("flips", fmt::format("{}", run.flips));
  RecordProperty("energy_error", fmt::format("{:.3e}", error));
  RecordProperty("second_over_first_half", fmt::format("{:.4f}", run.second_half / run.first_half));
}

TEST(RigidRotation, EnergyErrorIsSecondOrder) {
  const double dt = 0.01;
  for (const auto& [name, body] : {std::pair{"tumbling", kTumbling}, {"wobbling", kWobbling}}) {
    const EnergyRun coarse = run_free(body, 2.0 * dt, 100.0);
    const EnergyRun fine = run_free(body, dt, 100.0);
    const double error = std::max(fine.first_half, fine.second_half);
    const double ratio = std::max(coarse.first_half, coarse.second_half) / error;
    EXPECT_LT(error, kEnergyBound * dt * dt) << name;
    EXPECT_GT(ratio, 3.5) << name;
    EXPECT_LT(ratio, 4.5) << name;
    RecordProperty(fmt::format("{}_energy_error", name), fmt::format("{:.3e}", error));
    RecordProperty(fmt::format("{}_ratio", name), fmt::format("{:.4f}", ratio));
  }
}

// Euler's equations in the body frame, L' = L x omega with omega = I^-1 L, and the quaternion
// kinematics q' = q (0, omega) / 2, integrated by classical RK4.
struct Motion {
  Quaternion q;
  Vec3 body;  // body angular momentum
};

Motion rate(const Motion& m) {
  const Vec3 omega = m.body.cwiseQuotient(kTop);
  const Quaternion dq = m.q * Quaternion(0.0, omega.x(), omega.y(), omega.z());
  return {Quaternion(0.5 * dq.coeffs()), m.body.cross(omega)};
}

Motion advance(const Motion& m, const Motion& d, double h) {
  return {Quaternion(m.q.coeffs() + h * d.q.coeffs()), m.body + h * d.body};
}

Motion reference(const Vec3& body, double duration, int steps) {
  Motion m{start_orientation(), body};
  const double h = duration / steps;
  for (int n = 0; n < steps; ++n) {
    const Motion k1 = rate(m);
    const Motion k2 = rate(advance(m, k1, 0.5 * h));
    const Motion k3 = rate(advance(m, k2, 0.5 * h));
    const Motion k4 = rate(advance(m, k3, h));
    m.q.coeffs() +=
        h / 6.0 * (k1.q.coeffs() + 2.0 * k2.q.coeffs() + 2.0 * k3.q.coeffs() + k4.q.coeffs());
    m.body += h / 6.0 * (k1.body + 2.0 * k2.body + 2.0 * k3.body + k4.body);
  }
  m.q.normalize();
  return m;
}

// The orientation error (rad) and the body angular velocity error (relative) at `duration`.
struct TrajectoryError {
  double angle;
  double omega;
};

TrajectoryError trajectory_error(const Vec3& body, double dt, double duration,
                                 const Motion& exact) {
  const RigidRotor top(kTop);
  Quaternion q = start_orientation();
  const Vec3 momentum = q * body;
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int n = 0; n < steps; ++n)
    top.drift(q, momentum, dt);
  const Vec3 omega = (q.conjugate() * momentum).cwiseQuotient(kTop);
  const Vec3 expected = exact.body.cwiseQuotient(kTop);
  return {angle_between(exact.q, q), (omega - expected).norm() / expected.norm()};
}

TEST(RigidRotation, TrajectoryConvergesAtSecondOrderThroughAFlip) {
  const double duration = 20.0;
  const Motion exact = reference(kTumbling, duration, 40000);
  const Motion check = reference(kTumbling, duration, 20000);
  ASSERT_LT(angle_between(exact.q, check.q), 1e-11);
  const TrajectoryError coarse = trajectory_error(kTumbling, 0.02, duration, exact);
  const TrajectoryError fine = trajectory_error(kTumbling, 0.01, duration, exact);
  EXPECT_LT(fine.angle, 1e-6);
  EXPECT_LT(fine.omega, 3e-7);
  for (const double ratio : {coarse.angle / fine.angle, coarse.omega / fine.omega}) {
    EXPECT_GT(ratio, 3.5);
    EXPECT_LT(ratio, 4.5);
  }
  RecordProperty("angle_error", fmt::format("{:.3e}", fine.angle));
  RecordProperty("omega_error", fmt::format("{:.3e}", fine.omega));
  RecordProperty("angle_ratio", fmt::format("{:.4f}", coarse.angle / fine.angle));
}

// The spheres' rule of dem_solver.cpp: q turned by |omega| dt about omega = L / I.
Quaternion sphere_turn(const Quaternion& q, const Vec3& omega, double dt) {
  const Quaternion turn(Eigen::AngleAxisd(omega.norm() * dt, omega.normalized()));
  return (turn * q).normalized();
}

TEST(RigidRotation, EqualMomentsTurnAsTheSpheres) {
  const double inertia = 0.4;
  const RigidRotor sphere(Vec3::Constant(inertia));
  Quaternion q = start_orientation();
  Quaternion expected = q;
  Vec3 momentum(0.3, -0.5, 0.8);
  const double dt = 0.05;
  double deviation = 0.0;
  for (int n = 0; n < 1000; ++n) {
    const Vec3 torque(std::sin(0.1 * n), std::cos(0.3 * n), 0.5);
    kick_angular_momentum(momentum, torque, dt);
    EXPECT_LT((sphere.angular_velocity(q, momentum) - momentum / inertia).norm(),
              1e-14 * momentum.norm() / inertia);
    sphere.drift(q, momentum, dt);
    expected = sphere_turn(expected, momentum / inertia, dt);
    deviation = std::max(deviation, (q.coeffs() - expected.coeffs()).norm());
    kick_angular_momentum(momentum, torque, dt);
  }
  EXPECT_LT(deviation, 1e-14);
  RecordProperty("deviation", fmt::format("{:.1e}", deviation));
}

// I1 = I2: the body momentum precesses about axis 3 at (1/I3 - 1/I1) L3 and the body turns as a
// sphere of moment I1 about L; the splitting keeps only these two commuting flows, so it is exact
// at any step (here about 0.2 rad per step). Oblate (I3 the largest: the half steps vanish) and
// prolate (I3 the smallest: the two half steps are taken as one full step).
TEST(RigidRotation, SymmetricTopIsTurnedExactly) {
  for (const double i3 : {3.0, 1.0 / 3.0}) {
    const double i1 = 1.0;
    const RigidRotor top(Vec3(i1, i1, i3));
    const Quaternion start = start_orientation();
    const Vec3 body(0.8, -0.4, 1.5);
    const Vec3 momentum = start * body;
    Quaternion q = start;
    const double dt = 0.1;
    const int steps = 500;
    for (int n = 0; n < steps; ++n)
      top.drift(q, momentum, dt);
    const double t = steps * dt;
    const Quaternion spin(Eigen::AngleAxisd((1.0 / i3 - 1.0 / i1) * body.z() * t, Vec3::UnitZ()));
    const Quaternion exact =
        Quaternion(Eigen::AngleAxisd(momentum.norm() / i1 * t, momentum.normalized())) * start *
        spin;
    EXPECT_LT(angle_between(exact, q), 1e-12) << "I3 = " << i3;
    EXPECT_NEAR(top.kinetic_energy(q, momentum), top.kinetic_energy(start, momentum), 1e-14)
        << "I3 = " << i3;
  }
}

// From rest under a constant torque T, L = T t and, on a sphere or about a principal axis of
// the top, omega = T t / I; the half-step angular velocities grow linearly, so the angle turned,
// T t^2 / (2 I), is exact too.
TEST(RigidRotation, ConstantTorqueFromRestGivesOmegaTTOverI) {
  const double dt = 0.01;
  const int steps = 1000;
  const double t = steps * dt;
  const Quaternion start = start_orientation();
  struct Case {
    Vec3 moments;
    Vec3 torque;
    double inertia;
  };
  for (const Case& c : {Case{Vec3::Constant(0.4), Vec3(0.3, -0.2, 0.1), 0.4},
                        Case{kTop, start * Vec3(0.0, 0.0, 0.5), 3.0}}) {
    const RigidRotor body(c.moments);
    Quaternion q = start;
    Vec3 momentum = Vec3::Zero();
    for (int n = 0; n < steps; ++n) {
      kick_angular_momentum(momentum, c.torque, dt);
      body.drift(q, momentum, dt);
      kick_angular_momentum(momentum, c.torque, dt);
    }
    const Vec3 omega = c.torque * t / c.inertia;
    EXPECT_LT((body.angular_velocity(q, momentum) - omega).norm(), 1e-12 * omega.norm());
    const Quaternion turned(
        Eigen::AngleAxisd(0.5 * c.torque.norm() * t * t / c.inertia, c.torque.normalized()));
    EXPECT_LT(angle_between(turned * start, q), 1e-12);
  }
}

// The splitting is symmetric: the drift with -dt undoes the drift with dt.
TEST(RigidRotation, DriftRunBackReturnsTheStart) {
  const RigidRotor top(kTop);
  const Quaternion start = start_orientation();
  const Vec3 momentum = start * kTumbling;
  Quaternion q = start;
  for (const double dt : {0.05, -0.05}) {
    for (int n = 0; n < 1000; ++n)
      top.drift(q, momentum, dt);
  }
  EXPECT_LT(angle_between(start, q), 1e-12);
}

TEST(RigidRotation, MomentumAndAngularVelocityConvertBothWays) {
  const RigidRotor top(kTop);
  const Quaternion q = start_orientation();
  const Vec3 omega(0.2, -1.1, 0.7);
  const Vec3 momentum = top.angular_momentum(q, omega);
  EXPECT_LT((top.angular_velocity(q, momentum) - omega).norm(), 1e-14 * omega.norm());
  const Vec3 body = q.conjugate() * omega;
  EXPECT_NEAR(top.kinetic_energy(q, momentum), 0.5 * body.dot(body.cwiseProduct(kTop)), 1e-15);
  EXPECT_THROW(RigidRotor(Vec3(1.0, 0.0, 2.0)), std::invalid_argument);
}

}  // namespace
}  // namespace partimix::dem
