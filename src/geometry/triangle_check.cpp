#include "geometry/triangle_check.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::geometry {
namespace {

bool has_area(const Triangle& triangle) {
  const Vec3 a = triangle.corner[1] - triangle.corner[0];
  const Vec3 b = triangle.corner[2] - triangle.corner[0];
  const Vec3 c = triangle.corner[2] - triangle.corner[1];
  const double longest = std::max({a.squaredNorm(), b.squaredNorm(), c.squaredNorm()});
  return a.cross(b).norm() > 1e-12 * longest;
}

}  // namespace

TriangleSoup checked_triangles(TriangleSoup triangles, const Vec3& offset) {
  const std::size_t read = triangles.size();
  for (Triangle& triangle : triangles) {
    for (Vec3& corner : triangle.corner) {
      corner += offset;
      if (!corner.allFinite())
        throw InputError({}, "a corner coordinate (after scale and offset) is not finite");
    }
  }
  std::erase_if(triangles, [](const Triangle& triangle) { return !has_area(triangle); });
  if (triangles.empty()) {
    throw InputError({}, fmt::format("none of its {} triangles has an area (each has a repeated "
                                     "corner or its corners on a line)",
                                     read));
  }
  return triangles;
}

}  // namespace partimix::geometry
