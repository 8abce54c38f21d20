#include "geometry/plane_surface.hpp"

namespace partimix::geometry {

bool PlaneSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const double gap = (centre - point_).dot(normal_);
  if (gap > reach)
    return false;
  out = {centre - gap * normal_, normal_, gap};
  return true;
}

}  // namespace partimix::geometry
