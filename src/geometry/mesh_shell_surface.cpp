#include "geometry/mesh_shell_surface.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace partimix::geometry {

MeshShellSurface::MeshShellSurface(const TriangleSoup& triangles)
    : bvh_(std::make_shared<const TriangleBvh>(triangles)),
      lower_(Vec3::Constant(std::numeric_limits<double>::infinity())),
      upper_(Vec3::Constant(-std::numeric_limits<double>::infinity())) {
  for (const Triangle& triangle : triangles) {
    for (const Vec3& corner : triangle.corner) {
      lower_ = lower_.cwiseMin(corner);
      upper_ = upper_.cwiseMax(corner);
    }
  }
}

MeshShellSurface::MeshShellSurface(std::shared_ptr<const TriangleBvh> bvh, const Vec3& lower,
                                   const Vec3& upper)
    : bvh_(std::move(bvh)), lower_(lower), upper_(upper) {}

bool MeshShellSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const bool near_box = (centre.array() > lower_.array() - reach).all() &&
                        (centre.array() < upper_.array() + reach).all();
  if (!near_box)
    return false;
  const ClosestPoint closest = bvh_->nearest(centre);
  const double gap = std::sqrt(closest.distance_squared);
  if (gap > reach || gap == 0.0)
    return false;
  out = {closest.point, (centre - closest.point) / gap, gap};
  return true;
}

}  // namespace partimix::geometry
