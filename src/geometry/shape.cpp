#include "geometry/shape.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::geometry {

double Box::signed_distance(const Vec3& x) const {
  const Vec3 centre = 0.5 * (lo_ + hi_);
  const Vec3 half = 0.5 * (hi_ - lo_);
  const Vec3 d = (x - centre).cwiseAbs() - half;
  const double outside = d.cwiseMax(0.0).norm();
  const double inside = std::min(d.maxCoeff(), 0.0);
  return outside + inside;
}

double Cylinder::signed_distance(const Vec3& x) const {
  const double radial = std::hypot(x.x() - base_.x(), x.y() - base_.y()) - radius_;
  const double axial = std::abs(x.z() - (base_.z() + 0.5 * height_)) - 0.5 * height_;
  const double outside = std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
  const double inside = std::min(std::max(radial, axial), 0.0);
  return outside + inside;
}

}  // namespace partimix::geometry
