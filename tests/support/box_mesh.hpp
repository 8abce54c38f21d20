#pragma once
// Closed triangle meshes for geometry tests.
#include "geometry/stl_reader.hpp"

namespace partimix::test_support {

// The box [lo, hi] as 12 triangles, counter-clockwise seen from outside; the last two close the
// top (z = hi).
inline geometry::TriangleSoup box_triangles(const Vec3& lo, const Vec3& hi) {
  const auto vertex = [&](int i) {
    return Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  };
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  geometry::TriangleSoup triangles;
  for (const auto& q : quads) {
    triangles.push_back({{vertex(q[0]), vertex(q[1]), vertex(q[2])}});
    triangles.push_back({{vertex(q[0]), vertex(q[2]), vertex(q[3])}});
  }
  return triangles;
}

}  // namespace partimix::test_support
