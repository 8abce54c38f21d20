#include "geometry/cone_surface.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::geometry {

ConeSurface::ConeSurface(const Vec3& axis_point, const Vec3& axis, double radius_0, double radius_1,
                         double height)
    : axis_point_(axis_point),
      axis_(axis.normalized()),
      radius_0_(radius_0),
      length_(std::hypot(height, radius_1 - radius_0)) {
  slope_dz_ = height / length_;
  slope_dr_ = (radius_1 - radius_0) / length_;
}

// In the meridian plane through the centre, (z, r): the nearest point of the generator from
// (0, r0) to (z1, r1), mapped back with the radial unit vector of the centre.
bool ConeSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const Vec3 offset = centre - axis_point_;
  const double z = offset.dot(axis_);
  const Vec3 radial = offset - z * axis_;
  const double r = radial.norm();
  if (r == 0.0)
    return false;
  const Vec3 e_r = radial / r;
  const double along = std::clamp(z * slope_dz_ + (r - radius_0_) * slope_dr_, 0.0, length_);
  const double z_p = along * slope_dz_;
  const double r_p = radius_0_ + along * slope_dr_;
  const Vec3 point = axis_point_ + z_p * axis_ + r_p * e_r;
  const bool on_rim = along == 0.0 || along == length_;
  // Inward normal of the generator: (dr, -dz) in (z, r).
  const Vec3 inward = slope_dr_ * axis_ - slope_dz_ * e_r;
  const Vec3 normal = on_rim ? Vec3((centre - point).normalized()) : inward;
  const double gap = (centre - point).dot(normal);
  if (gap > reach || !std::isfinite(gap))
    return false;
  out = {point, normal, gap};
  return true;
}

}  // namespace partimix::geometry
