#include "dem/rigid_rotation.hpp"

#include <cmath>
#include <stdexcept>

namespace partimix::dem {
namespace {

// The exact flow of H_k = rate L_k^2 / 2 over dt, with L in the body frame: the body turns by
// theta = rate L_k dt about its axis k and L by -theta about the same axis (docs/dem.md,
// Rotation); L_k is unchanged, so the same step with -dt undoes it.
void turn_about_axis(Quaternion& q, Vec3& body_momentum, Eigen::Index axis, double rate,
                     double dt) {
  const double angle = rate * body_momentum[axis] * dt;
  if (angle == 0.0)
    return;
  const double s = std::sin(0.5 * angle);
  const double c = std::cos(0.5 * angle);
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
  const double angle = omega.norm() * dt;
  if (angle != 0.0)
    q = Quaternion(Eigen::AngleAxisd(angle, omega.normalized())) * q;
}

}  // namespace

RigidRotor::RigidRotor(const Vec3& moments) : moments_(moments) {
  if (!(moments.minCoeff() > 0.0))
    throw std::invalid_argument("rigid rotor: the principal moments must be positive");
  moments.minCoeff(&half_axis_);
  moments.maxCoeff(&full_axis_);
  if (half_axis_ == full_axis_)
    full_axis_ = (half_axis_ + 1) % 3;
  reference_ = moments[3 - half_axis_ - full_axis_];
  half_rate_ = 1.0 / moments[half_axis_] - 1.0 / reference_;
  full_rate_ = 1.0 / moments[full_axis_] - 1.0 / reference_;
}

Vec3 RigidRotor::angular_velocity(const Quaternion& q, const Vec3& momentum) const {
  return q * (q.conjugate() * momentum).cwiseQuotient(moments_);
}

Vec3 RigidRotor::angular_momentum(const Quaternion& q, const Vec3& omega) const {
  return q * (q.conjugate() * omega).cwiseProduct(moments_);
}

double RigidRotor::kinetic_energy(const Quaternion& q, const Vec3& momentum) const {
  const Vec3 body = q.conjugate() * momentum;
  return 0.5 * body.dot(body.cwiseQuotient(moments_));
}

// docs/dem.md, Rotation: half step about the smallest moment's axis, full step about the
// largest's, the sphere of the intermediate moment (which commutes with both), half step.
void RigidRotor::drift(Quaternion& q, const Vec3& momentum, double dt) const {
  Vec3 body = q.conjugate() * momentum;
  turn_about_axis(q, body, half_axis_, half_rate_, 0.5 * dt);
  turn_about_axis(q, body, full_axis_, full_rate_, dt);
  turn_as_sphere(q, momentum, reference_, dt);
  turn_about_axis(q, body, half_axis_, half_rate_, 0.5 * dt);
  q.normalize();
}

}  // namespace partimix::dem
