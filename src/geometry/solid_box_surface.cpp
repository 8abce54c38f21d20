#include "geometry/solid_box_surface.hpp"

namespace partimix::geometry {

bool SolidBoxSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const Vec3 clamped = centre.cwiseMax(lo_).cwiseMin(hi_);
  const Vec3 offset = centre - clamped;
  const double distance = offset.norm();
  if (distance > reach)
    return false;
  if (distance > 0.0) {
    out = {clamped, offset / distance, distance};
    return true;
  }
  nearest_face(centre, out);
  return true;
}

// Inside (or on) the box the clamp gives no direction: the face of least depth does.
void SolidBoxSurface::nearest_face(const Vec3& centre, SurfacePoint& out) const {
  double depth = centre.x() - lo_.x();
  int axis = 0;
  int side = -1;
  for (int a = 0; a < 3; ++a) {
    for (const int s : {-1, 1}) {
      const double d = s > 0 ? hi_[a] - centre[a] : centre[a] - lo_[a];
      if (d < depth) {
        depth = d;
        axis = a;
        side = s;
      }
    }
  }
  Vec3 point = centre;
  point[axis] = side > 0 ? hi_[axis] : lo_[axis];
  out = {point, static_cast<double>(side) * Vec3::Unit(axis), -depth};
}

}  // namespace partimix::geometry
