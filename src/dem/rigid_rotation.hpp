#pragma once
// The rotation of a rigid grain with three principal moments (docs/dem.md, "Superquadric
// grains", Rotation). The state of a grain is its world angular momentum L and its orientation q
// (body to world); velocity Verlet kicks L by dt/2 times the world torque, and the drift turns q
// by the torque-free motion over dt: the exact rotation of a sphere with the intermediate moment
// composed with exact turns about the other two body axes (a symmetric splitting, second order,
// symplectic and time-reversible). For I1 = I2 = I3 it is the spheres' rule: q turned by
// |omega| dt about omega = L / I.
#include <Eigen/Geometry>

#include "core/vec.hpp"

namespace partimix::dem {

using Quaternion = Eigen::Quaterniond;

// L += dt/2 torque (both in the world frame): the half kick of velocity Verlet.
inline void kick_angular_momentum(Vec3& momentum, const Vec3& torque, double dt) {
  momentum += 0.5 * dt * torque;
}

class RigidRotor {
 public:
  // Principal moments of inertia > 0 about the body axes x, y, z.
  explicit RigidRotor(const Vec3& moments);

  const Vec3& moments() const { return moments_; }
  // omega = Q I^-1 Q^T L, in the world frame; Q as a quaternion or as its rotation matrix.
  Vec3 angular_velocity(const Quaternion& q, const Vec3& momentum) const;
  Vec3 angular_velocity(const Mat3& rotation, const Vec3& momentum) const;
  // L = Q I Q^T omega, in the world frame.
  Vec3 angular_momentum(const Quaternion& q, const Vec3& omega) const;
  // E = L . omega / 2.
  double kinetic_energy(const Quaternion& q, const Vec3& momentum) const;
  // The torque-free motion over dt (dt < 0 runs it back): turns q, which stays normalised; the
  // world momentum L is a constant of this motion.
  void drift(Quaternion& q, const Vec3& momentum, double dt) const;

 private:
  Vec3 moments_;
  Vec3 inverse_moments_;
  double reference_ = 0.0;      // the intermediate moment: the sphere part of the splitting
  Eigen::Index half_axis_ = 0;  // the smallest moment's axis: two half steps
  Eigen::Index full_axis_ = 0;  // the largest moment's axis: one full step
  double half_rate_ = 0.0;      // 1 / I_k - 1 / I_reference on these axes
  double full_rate_ = 0.0;
};

}  // namespace partimix::dem
