#include "dem/mesh_wall.hpp"

#include <cmath>
#include <limits>

namespace partimix::dem {

MeshWall::MeshWall(const geometry::TriangleSoup& triangles)
    : bvh_(triangles),
      lower_(Vec3::Constant(std::numeric_limits<double>::infinity())),
      upper_(Vec3::Constant(-std::numeric_limits<double>::infinity())) {
  for (const geometry::Triangle& triangle : triangles) {
    for (const Vec3& corner : triangle.corner) {
      lower_ = lower_.cwiseMin(corner);
      upper_ = upper_.cwiseMax(corner);
    }
  }
}

bool MeshWall::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const bool near_box = (centre.array() > lower_.array() - reach).all() &&
                        (centre.array() < upper_.array() + reach).all();
  if (!near_box)
    return false;
  const geometry::ClosestPoint closest = bvh_.nearest(centre);
  const double gap = std::sqrt(closest.distance_squared);
  if (gap > reach || gap == 0.0)
    return false;
  out = {closest.point, (centre - closest.point) / gap, gap};
  return true;
}

}  // namespace partimix::dem
