#include "geometry/surface.hpp"

#include <limits>

namespace partimix::geometry {

int Surface::contacts(const Vec3& centre, double reach, std::span<SurfacePoint> out) const {
  SurfacePoint point;
  if (out.empty() || !nearest(centre, reach, point) || point.gap > reach)
    return 0;
  point.face = 0;
  out[0] = point;
  return 1;
}

int Surface::faces_near(const Vec3& centre, double reach, std::span<int> out) const {
  SurfacePoint point;
  if (out.empty() || !nearest(centre, reach, point) || point.gap > reach)
    return 0;
  out[0] = 0;
  return 1;
}

bool Surface::nearest_on_face(int /*face*/, const Vec3& point, double reach,
                              SurfacePoint& out) const {
  if (!nearest(point, reach, out))
    return false;
  out.face = 0;
  return true;
}

bool Surface::shadowed(const SurfacePoint& /*candidate*/, const SurfacePoint& /*deeper*/) const {
  return false;
}

}  // namespace partimix::geometry
