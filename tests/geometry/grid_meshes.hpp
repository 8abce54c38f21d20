#pragma once
// Triangle meshes of flat patches for the tests of walls of several faces (docs/dem.md, "Walls
// of several faces"): a parallelogram cut into n_u x n_v cells, each split along the same
// diagonal, so that an inner vertex belongs to six triangles and an inner edge to two.
#include <array>
#include <cmath>

#include "geometry/stl_reader.hpp"

namespace partimix::geometry::testing {

// The parallelogram origin + [0, n_u] u + [0, n_v] v, appended to `soup`. Each vertex is
// computed once, so that triangles share their corners bit for bit.
inline void add_patch(TriangleSoup& soup, const Vec3& origin, const Vec3& u, const Vec3& v, int n_u,
                      int n_v) {
  const auto vertex = [&](int i, int j) -> Vec3 { return origin + i * u + j * v; };
  for (int i = 0; i < n_u; ++i) {
    for (int j = 0; j < n_v; ++j) {
      const Vec3 a = vertex(i, j);
      const Vec3 b = vertex(i + 1, j);
      const Vec3 c = vertex(i + 1, j + 1);
      const Vec3 d = vertex(i, j + 1);
      soup.push_back(Triangle{{a, b, c}});
      soup.push_back(Triangle{{a, c, d}});
    }
  }
}

// The six faces of the cube [-half, half]^3, each cut into n x n cells.
inline TriangleSoup cube_mesh(double half, int n) {
  TriangleSoup soup;
  const double h = 2.0 * half / n;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 u = h * Vec3::Unit((axis + 1) % 3);
    const Vec3 v = h * Vec3::Unit((axis + 2) % 3);
    const Vec3 corner = -half * Vec3::Ones();
    add_patch(soup, corner, u, v, n, n);
    add_patch(soup, corner + 2.0 * half * Vec3::Unit(axis), u, v, n, n);
  }
  return soup;
}

// An L: the floor z = 0 for x in [0, n h] and the wall x = 0 for z in [0, n h], both for y in
// [-n h, n h]; the concave corner runs along the y axis.
inline TriangleSoup corner_mesh(double h, int n) {
  TriangleSoup soup;
  const Vec3 origin(0.0, -n * h, 0.0);
  add_patch(soup, origin, h * Vec3::UnitX(), h * Vec3::UnitY(), n, 2 * n);
  add_patch(soup, origin, h * Vec3::UnitZ(), h * Vec3::UnitY(), n, 2 * n);
  return soup;
}

// A roof: two flat parts meeting along the x axis (x in [-n h, n h]), each falling away from it
// at `slope` (rad) for n cells of h; the ridge is convex seen from above.
inline TriangleSoup roof_mesh(double slope, double h, int n) {
  TriangleSoup soup;
  const Vec3 origin(-n * h, 0.0, 0.0);
  for (const double side : {-1.0, 1.0}) {
    add_patch(soup, origin, h * Vec3::UnitX(),
              h * Vec3(0.0, side * std::cos(slope), -std::sin(slope)), 2 * n, n);
  }
  return soup;
}

}  // namespace partimix::geometry::testing
