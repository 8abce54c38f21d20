#include "geometry/drum_surface.hpp"

namespace partimix::geometry {

bool DrumSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const Vec3 offset = centre - axis_point_;
  const Vec3 radial = offset - offset.dot(axis_) * axis_;
  // Inside radius - reach of the axis the gap exceeds the reach: no square root needed.
  const double inner = radius_ - reach;
  if (inner > 0.0 && radial.squaredNorm() < inner * inner)
    return false;
  const double r = radial.norm();
  const double gap = radius_ - r;
  if (gap > reach || r == 0.0)
    return false;
  const Vec3 outward = radial / r;
  out = {centre + gap * outward, -outward, gap};
  return true;
}

}  // namespace partimix::geometry
