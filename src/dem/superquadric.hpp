#pragma once
// A superquadric grain's shape in its body frame (docs/dem.md, "Superquadric grains"; seed 002
// eq. 1): F(X) = (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 - 1, negative inside. Its value,
// gradient and Hessian (for the midway-point Newton iteration), volume and principal moments of
// inertia (Jaklič, Leonardis & Solina 2000), and a bounding radius.

#include "core/vec.hpp"

namespace partimix::dem {

class Superquadric {
 public:
  // Half-axes a, b, c > 0 and blockiness n1, n2 >= 2 (n1 along z, n2 in the x-y plane).
  Superquadric(const Vec3& half_axes, double n1, double n2);

  double value(const Vec3& x) const;
  Vec3 gradient(const Vec3& x) const;
  Mat3 hessian(const Vec3& x) const;
  // The surface point whose outward normal is along `direction` (any length > 0): the point
  // farthest along it, in closed form (docs/dem.md, "Walls and superquadrics"); for an
  // ellipsoid D^2 d / |D d| with D = diag(a, b, c).
  Vec3 support(const Vec3& direction) const;

  const Vec3& half_axes() const { return axes_; }
  double n1() const { return n1_; }
  double n2() const { return n2_; }
  bool is_ellipsoid() const { return n1_ == 2.0 && n2_ == 2.0; }
  double volume() const { return volume_; }
  // The radius of the sphere of the same volume (the Hertz radius, docs/dem.md).
  double equivalent_radius() const { return equivalent_radius_; }
  // Principal moments of inertia per unit density, about the body axes x, y, z.
  const Vec3& unit_inertia() const { return unit_inertia_; }
  // The radius of a sphere about the centre that holds the whole grain.
  double bounding_radius() const { return bounding_radius_; }

 private:
  Vec3 axes_;
  double n1_;
  double n2_;
  double volume_ = 0.0;
  double equivalent_radius_ = 0.0;
  Vec3 unit_inertia_ = Vec3::Zero();
  double bounding_radius_ = 0.0;
};

}  // namespace partimix::dem
