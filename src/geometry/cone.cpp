#include "geometry/cone.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/cone_surface.hpp"
#include "geometry/meridian.hpp"

namespace partimix::geometry {
namespace {

// How far a circle of radius r normal to the unit axis reaches along each coordinate axis.
Vec3 circle_extent(const Vec3& unit_axis, double r) {
  const Vec3 squares = unit_axis.cwiseProduct(unit_axis);
  return (Vec3::Ones() - squares).cwiseMax(0.0).cwiseSqrt() * r;
}

}  // namespace

Cone::Cone(const Vec3& axis_point, const Vec3& axis, double radius_0, double radius_1,
           double height)
    : axis_point_(axis_point),
      given_axis_(axis),
      axis_(axis.normalized()),
      radius_0_(radius_0),
      radius_1_(radius_1),
      height_(height) {
  const Vec3 top = axis_point_ + height_ * axis_;
  const Vec3 extent_0 = circle_extent(axis_, radius_0_);
  const Vec3 extent_1 = circle_extent(axis_, radius_1_);
  lower_ = (axis_point_ - extent_0).cwiseMin(top - extent_1);
  upper_ = (axis_point_ + extent_0).cwiseMax(top + extent_1);
}

double Cone::signed_distance(const Vec3& x) const {
  const Meridian m = meridian(x, axis_point_, axis_);
  const double side = meridian_segment_distance(m.z, m.r, 0.0, radius_0_, height_, radius_1_);
  const double bottom = meridian_segment_distance(m.z, m.r, 0.0, 0.0, 0.0, radius_0_);
  const double top = meridian_segment_distance(m.z, m.r, height_, 0.0, height_, radius_1_);
  const double distance = std::min({side, bottom, top});
  const bool inside =
      m.z > 0.0 && m.z < height_ && m.r < radius_0_ + (radius_1_ - radius_0_) * (m.z / height_);
  return inside ? -distance : distance;
}

bool Cone::beyond_open_end(const Vec3& x, const std::vector<Face>& /*open_faces*/) const {
  const double z = (x - axis_point_).dot(axis_);
  return z < 0.0 || z > height_;
}

std::unique_ptr<Surface> Cone::make_surface(bool /*solid*/,
                                            const std::vector<Face>& /*open_faces*/) const {
  return std::make_unique<ConeSurface>(axis_point_, given_axis_, radius_0_, radius_1_, height_);
}

}  // namespace partimix::geometry
