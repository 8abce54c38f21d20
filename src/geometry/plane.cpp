#include "geometry/plane.hpp"

#include <limits>

#include "geometry/plane_surface.hpp"

namespace partimix::geometry {

Plane::Plane(const Vec3& point, const Vec3& normal)
    : point_(point),
      given_normal_(normal),
      normal_(normal.normalized()),
      lower_(Vec3::Constant(-std::numeric_limits<double>::infinity())),
      upper_(Vec3::Constant(std::numeric_limits<double>::infinity())) {
  // Normal to axis k (the other components exactly zero): the half-space x_k <= point_k when
  // the normal points up the axis, x_k >= point_k when it points down.
  for (int k = 0; k < 3; ++k) {
    const bool along_k = normal_[(k + 1) % 3] == 0.0 && normal_[(k + 2) % 3] == 0.0;
    if (along_k && normal_[k] > 0.0)
      upper_[k] = point_[k];
    if (along_k && normal_[k] < 0.0)
      lower_[k] = point_[k];
  }
}

double Plane::signed_distance(const Vec3& x) const {
  return (x - point_).dot(normal_);
}

std::unique_ptr<Surface> Plane::make_surface(bool /*solid*/,
                                             const std::vector<Face>& /*open_faces*/) const {
  return std::make_unique<PlaneSurface>(point_, given_normal_);
}

}  // namespace partimix::geometry
