#include "geometry/drum.hpp"

#include <limits>

#include "geometry/drum_surface.hpp"
#include "geometry/meridian.hpp"

namespace partimix::geometry {

Drum::Drum(const Vec3& axis_point, const Vec3& axis, double radius)
    : axis_point_(axis_point),
      given_axis_(axis),
      axis_(axis.normalized()),
      radius_(radius),
      lower_(Vec3::Constant(-std::numeric_limits<double>::infinity())),
      upper_(Vec3::Constant(std::numeric_limits<double>::infinity())) {
  // A circle of radius R normal to the unit axis a spans R sqrt(1 - a_k^2) along axis k: R
  // where a_k = 0; where a_k != 0 the cylinder runs to infinity along k.
  for (int k = 0; k < 3; ++k) {
    if (axis_[k] == 0.0) {
      lower_[k] = axis_point_[k] - radius_;
      upper_[k] = axis_point_[k] + radius_;
    }
  }
}

// The same arithmetic as DrumSurface, so that the gap is exactly minus this.
double Drum::signed_distance(const Vec3& x) const {
  return meridian(x, axis_point_, axis_).r - radius_;
}

std::unique_ptr<Surface> Drum::make_surface(bool /*solid*/,
                                            const std::vector<Face>& /*open_faces*/) const {
  return std::make_unique<DrumSurface>(axis_point_, given_axis_, radius_);
}

}  // namespace partimix::geometry
