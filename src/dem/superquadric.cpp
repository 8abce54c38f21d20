#include "dem/superquadric.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace partimix::dem {
namespace {

double signum(double v) {
  return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

// |t|^n, its first and second derivatives in t.
struct Power {
  double value;
  double first;
  double second;
};

Power power(double t, double n) {
  const double u = std::abs(t);
  return {std::pow(u, n), n * std::pow(u, n - 1.0) * signum(t),
          n * (n - 1.0) * std::pow(u, n - 2.0)};
}

// The powers of the scaled coordinates, and s = |x/a|^n2 + |y/b|^n2 with the derivatives of
// s^(n1/n2) with respect to s (on the z axis, where s = 0: their limits for n1 = n2, else zero).
struct Terms {
  Power x, y, z;
  double ds = 0.0;
  double dds = 0.0;
};

Terms terms(const Vec3& x, const Vec3& axes, double n1, double n2) {
  Terms t{power(x.x() / axes.x(), n2), power(x.y() / axes.y(), n2), power(x.z() / axes.z(), n1)};
  const double s = t.x.value + t.y.value;
  const double p = n1 / n2;
  if (s > 0.0) {
    t.ds = p * std::pow(s, p - 1.0);
    t.dds = p * (p - 1.0) * std::pow(s, p - 2.0);
  } else if (p == 1.0) {  // s^1 on the z axis too (an ellipsoid's curvature there)
    t.ds = 1.0;
  }
  return t;
}

}  // namespace

Superquadric::Superquadric(const Vec3& half_axes, double n1, double n2)
    : axes_(half_axes), n1_(n1), n2_(n2) {
  if (half_axes.minCoeff() <= 0.0 || n1 < 2.0 || n2 < 2.0)
    throw std::invalid_argument("superquadric: half-axes must be positive and n1, n2 >= 2");
  // docs/dem.md, "Volume and inertia" (Jaklič et al. 2000), e1 = 2 / n1, e2 = 2 / n2.
  const double e1 = 2.0 / n1;
  const double e2 = 2.0 / n2;
  const double a = axes_.x();
  const double b = axes_.y();
  const double c = axes_.z();
  const double abc = a * b * c * e1 * e2;
  volume_ = 2.0 * abc * std::beta(e1 / 2.0 + 1.0, e1) * std::beta(e2 / 2.0, e2 / 2.0);
  equivalent_radius_ = std::cbrt(0.75 * volume_ / std::numbers::pi);
  const double in_plane = std::beta(3.0 * e2 / 2.0, e2 / 2.0) * std::beta(e1 / 2.0, 2.0 * e1 + 1.0);
  const double along_z =
      4.0 * std::beta(e2 / 2.0, e2 / 2.0 + 1.0) * std::beta(3.0 * e1 / 2.0, e1 + 1.0);
  unit_inertia_ = 0.5 * abc *
                  Vec3(b * b * in_plane + c * c * along_z, a * a * in_plane + c * c * along_z,
                       (a * a + b * b) * in_plane);
  // An ellipsoid reaches its longest half-axis; any other superquadric lies in the box of its
  // half-axes.
  bounding_radius_ = n1 == 2.0 && n2 == 2.0 ? axes_.maxCoeff() : axes_.norm();
}

double Superquadric::value(const Vec3& x) const {
  const double s =
      std::pow(std::abs(x.x() / axes_.x()), n2_) + std::pow(std::abs(x.y() / axes_.y()), n2_);
  return std::pow(s, n1_ / n2_) + std::pow(std::abs(x.z() / axes_.z()), n1_) - 1.0;
}

Vec3 Superquadric::gradient(const Vec3& x) const {
  const Terms t = terms(x, axes_, n1_, n2_);
  return {t.ds * t.x.first / axes_.x(), t.ds * t.y.first / axes_.y(), t.z.first / axes_.z()};
}

Mat3 Superquadric::hessian(const Vec3& x) const {
  const Terms t = terms(x, axes_, n1_, n2_);
  const double gx = t.x.first / axes_.x();
  const double gy = t.y.first / axes_.y();
  Mat3 h = Mat3::Zero();
  h(0, 0) = t.dds * gx * gx + t.ds * t.x.second / (axes_.x() * axes_.x());
  h(1, 1) = t.dds * gy * gy + t.ds * t.y.second / (axes_.y() * axes_.y());
  h(0, 1) = h(1, 0) = t.dds * gx * gy;
  h(2, 2) = t.z.second / (axes_.z() * axes_.z());
  return h;
}

// docs/dem.md, "Walls and superquadrics": with (A, B, C) = (a |d_x|, b |d_y|, c |d_z|) and
// S = A^(n2/(n2-1)) + B^(n2/(n2-1)), the point is t (A^(1/(n2-1)), B^(1/(n2-1))) in the scaled
// x-y coordinates and (lambda C)^(1/(n1-1)) along z, lambda = t^(n1-1) S^(n1/n2-1).
Vec3 Superquadric::support(const Vec3& direction) const {
  if (is_ellipsoid()) {
    const Vec3 scaled = axes_.cwiseProduct(direction);
    return axes_.cwiseProduct(scaled) / scaled.norm();
  }
  const Vec3 d = direction.normalized();
  const double big_a = axes_.x() * std::abs(d.x());
  const double big_b = axes_.y() * std::abs(d.y());
  const double big_c = axes_.z() * std::abs(d.z());
  const double q2 = n2_ / (n2_ - 1.0);
  const double q1 = n1_ / (n1_ - 1.0);
  const double s = std::pow(big_a, q2) + std::pow(big_b, q2);
  if (s == 0.0)
    return {0.0, 0.0, signum(d.z()) * axes_.z()};
  const double p = n1_ / n2_;
  const double t =
      std::pow(std::pow(s, p) + std::pow(s, (p - 1.0) * q1) * std::pow(big_c, q1), -1.0 / n1_);
  const double lambda = std::pow(t, n1_ - 1.0) * std::pow(s, p - 1.0);
  return {signum(d.x()) * axes_.x() * t * std::pow(big_a, 1.0 / (n2_ - 1.0)),
          signum(d.y()) * axes_.y() * t * std::pow(big_b, 1.0 / (n2_ - 1.0)),
          signum(d.z()) * axes_.z() * std::pow(lambda * big_c, 1.0 / (n1_ - 1.0))};
}

}  // namespace partimix::dem
