#include "dem/superquadric.hpp"

#include <cmath>
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
  const double s = power(x.x() / axes_.x(), n2_).value + power(x.y() / axes_.y(), n2_).value;
  return std::pow(s, n1_ / n2_) + power(x.z() / axes_.z(), n1_).value - 1.0;
}

Vec3 Superquadric::gradient(const Vec3& x) const {
  const Power px = power(x.x() / axes_.x(), n2_);
  const Power py = power(x.y() / axes_.y(), n2_);
  const Power pz = power(x.z() / axes_.z(), n1_);
  const double s = px.value + py.value;
  const double p = n1_ / n2_;
  const double ds = s > 0.0 ? p * std::pow(s, p - 1.0) : 0.0;
  return {ds * px.first / axes_.x(), ds * py.first / axes_.y(), pz.first / axes_.z()};
}

Mat3 Superquadric::hessian(const Vec3& x) const {
  const Power px = power(x.x() / axes_.x(), n2_);
  const Power py = power(x.y() / axes_.y(), n2_);
  const Power pz = power(x.z() / axes_.z(), n1_);
  const double s = px.value + py.value;
  const double p = n1_ / n2_;
  Mat3 h = Mat3::Zero();
  if (s > 0.0) {
    const double ds = p * std::pow(s, p - 1.0);
    const double dds = p * (p - 1.0) * std::pow(s, p - 2.0);
    const Vec3 g(px.first / axes_.x(), py.first / axes_.y(), 0.0);
    h(0, 0) = dds * g.x() * g.x() + ds * px.second / (axes_.x() * axes_.x());
    h(1, 1) = dds * g.y() * g.y() + ds * py.second / (axes_.y() * axes_.y());
    h(0, 1) = h(1, 0) = dds * g.x() * g.y();
  }
  h(2, 2) = pz.second / (axes_.z() * axes_.z());
  return h;
}

}  // namespace partimix::dem
