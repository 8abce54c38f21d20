#include "dem/rigid_rotation.hpp"

#include <cmath>
#include <stdexcept>

namespace partimix::dem {
namespace {

// sin x and cos x. The turns of one step are small, and for |x| < 0.05 the Taylor series to x^9
// and x^10 are exact in double precision (the first term left out, x^11 / 11!, is below 1e-21
// of the sum) and cost a few multiplications; larger x go to the library. The factors are
// reciprocals: a division by a constant stays a division (some 13 cycles, each waiting for the
// last) unless the constant is a power of two.
void sin_cos(double x, double& sine, double& cosine) {
  if (std::abs(x) >= 0.05) {
    sine = std::sin(x);
    cosine = std::cos(x);
    return;
  }
  constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0, k72 = 1.0 / 72.0;
  constexpr double k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0, k90 = 1.0 / 90.0;
  const double x2 = x * x;
  sine = x * (1.0 - x2 * k6 * (1.0 - x2 * k20 * (1.0 - x2 * k42 * (1.0 - x2 * k72))));
  cosine =
      1.0 - 0.5 * x2 * (1.0 - x2 * k12 * (1.0 - x2 * k30 * (1.0 - x2 * k56 * (1.0 - x2 * k90))));
}

// The exact flow of H_k = rate L_k^2 / 2 over dt, with L in the body frame: the body turns by
// theta = rate L_k dt about its axis k and L by -theta about the same axis (docs/dem.md,
// Rotation); L_k is unchanged, so the same step with -dt undoes it.
void turn_about_axis(Quaternion& q, Vec3& body_momentum, Eigen::Index axis, double rate,
                     double dt) {
  const double angle = rate * body_momentum[axis] * dt;
  if (angle == 0.0)
    return;
  double s = 0.0;
  double c = 1.0;
  sin_cos(0.5 * angle, s, c);
  Quaternion turn(c, 0.0, 0.0, 0.0);
  turn.vec()[axis] = s;
  q = q * turn;
  const Eigen::Index i = (axis + 1) % 3;
  const Eigen::Index j = (axis + 2) % 3;
  const double sine = 2.0 * s * c;
  const double cosine = 1.0 - 2.0 * s * s;
  const double li = body_momentum[i];
  const double lj = body_momentum[j];
  body_momentum[i] = cosine * li + sine * lj;
  body_momentum[j] = cosine * lj - sine * li;
}

// The exact flow of |L|^2 / (2 I): q turned by |omega| dt about omega = L / I (world frame),
// as the spheres turn in dem_solver.cpp.
void turn_as_sphere(Quaternion& q, const Vec3& momentum, double inertia, double dt) {
  const Vec3 omega = momentum / inertia;
  const double rate = omega.norm();
  if (rate * dt == 0.0)
    return;
  double s = 0.0;
  double c = 1.0;
  sin_cos(0.5 * rate * dt, s, c);
  const Vec3 axis_sine = (s / rate) * omega;
  q = Quaternion(c, axis_sine.x(), axis_sine.y(), axis_sine.z()) * q;
}

}  // namespace

RigidRotor::RigidRotor(const Vec3& moments) : moments_(moments) {
  if (!(moments.minCoeff() > 0.0))
    throw std::invalid_argument("rigid rotor: the principal moments must be positive");
  inverse_moments_ = moments.cwiseInverse();
  moments.minCoeff(&half_axis_);
  moments.maxCoeff(&full_axis_);
  if (half_axis_ == full_axis_)
    full_axis_ = (half_axis_ + 1) % 3;
  reference_ = moments[3 - half_axis_ - full_axis_];
  half_rate_ = 1.0 / moments[half_axis_] - 1.0 / reference_;
  full_rate_ = 1.0 / moments[full_axis_] - 1.0 / reference_;
}

Vec3 RigidRotor::angular_velocity(const Quaternion& q, const Vec3& momentum) const {
  return q * (q.conjugate() * momentum).cwiseProduct(inverse_moments_);
}

Vec3 RigidRotor::angular_velocity(const Mat3& rotation, const Vec3& momentum) const {
  return rotation * (rotation.transpose() * momentum).cwiseProduct(inverse_moments_);
}

Vec3 RigidRotor::angular_momentum(const Quaternion& q, const Vec3& omega) const {
  return q * (q.conjugate() * omega).cwiseProduct(moments_);
}

double RigidRotor::kinetic_energy(const Quaternion& q, const Vec3& momentum) const {
  const Vec3 body = q.conjugate() * momentum;
  return 0.5 * body.dot(body.cwiseQuotient(moments_));
}

// docs/dem.md, Rotation: half step about the smallest moment's axis, full step about the
// largest's, the sphere of the intermediate moment (which commutes with both), half step. A
// symmetric top has full_rate_ = 0 (prolate) or half_rate_ = 0 (oblate): its two flows left
// commute, so one full step of each is the same exact flow with a turn less.
void RigidRotor::drift(Quaternion& q, const Vec3& momentum, double dt) const {
  Vec3 body = q.conjugate() * momentum;
  if (full_rate_ == 0.0) {
    turn_about_axis(q, body, half_axis_, half_rate_, dt);
  } else {
    turn_about_axis(q, body, half_axis_, half_rate_, 0.5 * dt);
    turn_about_axis(q, body, full_axis_, full_rate_, dt);
    turn_about_axis(q, body, half_axis_, half_rate_, 0.5 * dt);
  }
  turn_as_sphere(q, momentum, reference_, dt);
  q.normalize();
}

}  // namespace partimix::dem
