// Triangle meshes as shapes: the signed distance of a meshed box equals the analytic box
// distance inside, outside, on faces and near edges and corners; lattices filled or walled from
// the mesh equal those of the Box; a tetrahedron, a faceted sphere and a cube with a pyramid
// dented into its top (concave edges and a concave corner) get the brute-force distance over all
// triangles and the right side; inside-out meshes are turned over; meshes that do not close a
// volume are refused.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "geometry/lattice.hpp"
#include "geometry/triangle_bvh.hpp"
#include "geometry/triangle_mesh.hpp"
#include "support/box_mesh.hpp"

namespace partimix::geometry {
namespace {

using test_support::box_triangles;

TriangleSoup unit_cube() {
  return box_triangles(Vec3::Zero(), Vec3::Ones());
}

// The unit cube less the pyramid with the top face as base and its apex at the centre.
TriangleSoup dented_cube() {
  TriangleSoup triangles = unit_cube();
  triangles.resize(10);
  const Vec3 apex(0.5, 0.5, 0.5);
  const Vec3 top[4] = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int k = 0; k < 4; ++k) {
    triangles.push_back({{top[k], top[(k + 1) % 4], apex}});
  }
  return triangles;
}

bool inside_dented_cube(const Vec3& x) {
  const bool in_cube = (x.array() > 0.0).all() && (x.array() < 1.0).all();
  const bool in_dent = x.z() - 0.5 >= std::max(std::abs(x.x() - 0.5), std::abs(x.y() - 0.5));
  return in_cube && !in_dent;
}

// The octahedron with each triangle split into four `levels` times, corners on the unit sphere.
TriangleSoup faceted_sphere(int levels) {
  TriangleSoup triangles;
  for (int octant = 0; octant < 8; ++octant) {
    const Vec3 s(octant & 1 ? -1.0 : 1.0, octant & 2 ? -1.0 : 1.0, octant & 4 ? -1.0 : 1.0);
    Triangle t{{Vec3(s.x(), 0, 0), Vec3(0, s.y(), 0), Vec3(0, 0, s.z())}};
    if (s.prod() < 0.0) {
      std::swap(t.corner[1], t.corner[2]);
    }
    triangles.push_back(t);
  }
  for (int level = 0; level < levels; ++level) {
    TriangleSoup finer;
    for (const Triangle& t : triangles) {
      const auto& c = t.corner;
      const Vec3 m01 = (c[0] + c[1]).normalized();
      const Vec3 m12 = (c[1] + c[2]).normalized();
      const Vec3 m20 = (c[2] + c[0]).normalized();
      finer.insert(finer.end(),
                   {{{c[0], m01, m20}}, {{m01, c[1], m12}}, {{m20, m12, c[2]}}, {{m01, m12, m20}}});
    }
    triangles = finer;
  }
  return triangles;
}

bool inside_convex(const TriangleSoup& triangles, const Vec3& x) {
  return std::ranges::all_of(triangles, [&](const Triangle& t) {
    const auto& c = t.corner;
    return (x - c[0]).dot((c[1] - c[0]).cross(c[2] - c[0])) < 0.0;
  });
}

double brute_force_distance(const TriangleSoup& triangles, const Vec3& x) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangles) {
    nearest = std::min(nearest, closest_point_on_triangle(t, x).distance_squared);
  }
  return std::sqrt(nearest);
}

std::vector<Vec3> random_points(int count, double from, double to) {
  std::mt19937 generator(20240611u);
  std::uniform_real_distribution<double> coordinate(from, to);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    const double x = coordinate(generator);
    const double y = coordinate(generator);
    points.emplace_back(x, y, coordinate(generator));
  }
  return points;
}

// Signed distances against `inside` and the brute force, skipping points closer to the surface
// than round-off can decide.
template <class Inside>
void expect_matches_brute_force(const TriangleSoup& triangles, Inside&& inside, int count) {
  const TriangleMesh mesh(triangles);
  for (const Vec3& x : random_points(count, -0.7, 1.7)) {
    const double distance = brute_force_distance(triangles, x);
    const double signed_distance = mesh.signed_distance(x);
    EXPECT_NEAR(std::abs(signed_distance), distance, 1e-14) << x.transpose();
    if (distance > 1e-9) {
      EXPECT_EQ(signed_distance < 0.0, inside(x)) << x.transpose();
    }
  }
}

TEST(TriangleMesh, CubeDistanceAtChosenPointsIsTheBoxDistance) {
  const TriangleMesh mesh(unit_cube());
  const Box box(Vec3::Zero(), Vec3::Ones());
  const Vec3 points[] = {
      {0.5, 0.5, 0.5},    {0.3, 0.3, 0.9},    {0.95, 0.9, 0.5},
      {0.99, 0.99, 0.99},  // inside
      {1.5, 0.5, 0.5},    {0.3, 0.3, 1.2},    {-0.4, 0.5, 0.5},
      {0.7, 0.2, -1e-3},                                                      // beyond a face
      {1.2, 1.1, 0.5},    {-0.1, 0.5, -0.3},  {0.5, 1.0 + 1e-9, 1.0 + 2e-9},  // near an edge
      {1.1, 1.2, -0.3},   {-1.0, -1.0, -1.0}, {1.0 + 1e-7, 1.0, 1.0},         // near a corner
      {1.0, 0.3, 0.7},    {0.5, 0.5, 0.0},    {0.3, 0.3, 1.0},                // on a face
      {1.0, 1.0, 0.5},    {0.0, 1.0, 1.0},    {1.0, 1.0, 1.0}};               // edge, corner
  for (const Vec3& x : points) {
    EXPECT_NEAR(mesh.signed_distance(x), box.signed_distance(x), 1e-12) << x.transpose();
  }
  EXPECT_EQ(mesh.triangle_count(), 12u);
  EXPECT_EQ(mesh.lower(), Vec3::Zero());
  EXPECT_EQ(mesh.upper(), Vec3::Ones());
}

TEST(TriangleMesh, BoxDistanceAtRandomPointsIsTheBoxDistance) {
  const Vec3 lo(-0.3, 0.2, 1.1);
  const Vec3 hi(0.45, 0.9, 1.6);
  const TriangleMesh mesh(box_triangles(lo, hi));
  const Box box(lo, hi);
  for (const Vec3& unit : random_points(20000, -0.5, 1.5)) {
    const Vec3 x = lo + unit.cwiseProduct(hi - lo);
    EXPECT_NEAR(mesh.signed_distance(x), box.signed_distance(x), 1e-12) << x.transpose();
  }
}

TEST(TriangleMesh, RotatedBoxDistanceIsTheBoxDistanceInTheBoxFrame) {
  const Vec3 lo(-0.3, 0.2, 1.1);
  const Vec3 hi(0.45, 0.9, 1.6);
  const Mat3 rotation =
      Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  TriangleSoup rotated = box_triangles(lo, hi);
  for (Triangle& t : rotated) {
    for (Vec3& c : t.corner) {
      c = rotation * c;
    }
  }
  const TriangleMesh mesh(rotated);
  const Box box(lo, hi);
  for (const Vec3& unit : random_points(20000, -0.5, 1.5)) {
    const Vec3 x = lo + unit.cwiseProduct(hi - lo);
    EXPECT_NEAR(mesh.signed_distance(rotation * x), box.signed_distance(x), 1e-12) << x.transpose();
  }
}

TEST(TriangleMesh, FillAndWallLayersOfTheMeshBoxAreThoseOfTheBox) {
  const Vec3 lo(0.013, -0.2, 0.1);
  const Vec3 hi(0.5, 0.3, 0.46);
  const TriangleMesh mesh(box_triangles(lo, hi));
  const Box box(lo, hi);
  const Domain domain;
  const auto filled = fill(mesh, 0.02, domain);
  EXPECT_EQ(filled.size(), 24u * 25u * 18u);
  EXPECT_EQ(filled, fill(box, 0.02, domain));
  const std::vector<Face> open_top{Face{2, 1}};
  const auto walls = wall_layers(mesh, 0.02, 3, open_top, domain);
  EXPECT_FALSE(walls.empty());
  EXPECT_EQ(walls, wall_layers(box, 0.02, 3, open_top, domain));
}

TEST(TriangleMesh, TetrahedronDistances) {
  const Vec3 o(0.0, 0.0, 0.0), x(1.0, 0.0, 0.0), y(0.0, 1.0, 0.0), z(0.0, 0.0, 1.0);
  const TriangleMesh mesh({{{o, y, x}}, {{o, x, z}}, {{o, z, y}}, {{x, y, z}}});
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.1, 0.1, 0.1)), -0.1, 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(1.0, 1.0, 1.0)), 2.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(-1.0, -2.0, -2.0)), 3.0, 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.5, -1.0, 0.25)), 1.0, 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(2.0, 2.0, 0.0)), 3.0 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.25, 0.25, 0.25)), -0.25 / std::sqrt(3.0), 1e-15);
}

TEST(TriangleMesh, FacetedSphereMatchesBruteForceAndItsFacePlanes) {
  const TriangleSoup sphere = faceted_sphere(3);
  ASSERT_EQ(sphere.size(), 512u);
  expect_matches_brute_force(
      sphere, [&](const Vec3& x) { return inside_convex(sphere, x); }, 1500);
}

TEST(TriangleMesh, ConcaveEdgesAndCornerOfADentedCubeGetTheRightSide) {
  expect_matches_brute_force(dented_cube(), inside_dented_cube, 20000);
  const TriangleMesh mesh(dented_cube());
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.5, 0.5, 0.45)), -0.05, 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.5, 0.5, 0.6)), 0.1 / std::sqrt(2.0), 1e-15);
}

TEST(TriangleMesh, HierarchyFindsTheBruteForceNearestTriangle) {
  const TriangleSoup sphere = faceted_sphere(4);
  const TriangleBvh bvh(sphere);
  ASSERT_EQ(bvh.size(), 2048u);
  for (const Vec3& x : random_points(600, -1.5, 1.5)) {
    const ClosestPoint nearest = bvh.nearest(x);
    EXPECT_NEAR(std::sqrt(nearest.distance_squared), brute_force_distance(sphere, x), 1e-15);
    EXPECT_EQ(closest_point_on_triangle(sphere[nearest.triangle], x).distance_squared,
              nearest.distance_squared);
  }
}

TEST(TriangleMesh, InsideOutMeshIsTurnedOverAndTranslationMovesIt) {
  TriangleSoup reversed = unit_cube();
  for (Triangle& t : reversed) {
    std::swap(t.corner[0], t.corner[1]);
  }
  const Vec3 shift(1.0, -2.0, 3.5);
  const TriangleMesh mesh(reversed, shift);
  const Box box(shift, shift + Vec3::Ones());
  EXPECT_EQ(mesh.lower(), box.lower());
  EXPECT_EQ(mesh.upper(), box.upper());
  for (const Vec3& unit : random_points(2000, -0.5, 1.5)) {
    const Vec3 x = shift + unit;
    EXPECT_NEAR(mesh.signed_distance(x), box.signed_distance(x), 1e-12) << x.transpose();
  }
}

TEST(TriangleMesh, TrianglesWithTwoEqualCornersAreDropped) {
  TriangleSoup cube = unit_cube();
  cube.push_back({{Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}});
  cube.push_back({{Vec3(5, 5, 5), Vec3(0, 0, 0), Vec3(5, 5, 5)}});
  const TriangleMesh mesh(cube);
  EXPECT_EQ(mesh.triangle_count(), 12u);
  EXPECT_EQ(mesh.upper(), Vec3::Ones());
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.9, 0.5, 0.5)), -0.1, 1e-15);
}

std::string mesh_error(const TriangleSoup& triangles) {
  try {
    const TriangleMesh mesh(triangles);
  } catch (const InputError& error) {
    return error.message();
  }
  return "no error";
}

TEST(TriangleMesh, MeshesThatDoNotCloseAVolumeAreRefused) {
  TriangleSoup open = unit_cube();
  open.pop_back();
  EXPECT_NE(mesh_error(open).find("not closed"), std::string::npos) << mesh_error(open);

  TriangleSoup flipped = unit_cube();
  std::swap(flipped[3].corner[1], flipped[3].corner[2]);
  EXPECT_NE(mesh_error(flipped).find("not consistently oriented"), std::string::npos)
      << mesh_error(flipped);

  TriangleSoup two_cubes = unit_cube();
  const TriangleSoup neighbour = box_triangles(Vec3(1, 1, 0), Vec3(2, 2, 1));
  two_cubes.insert(two_cubes.end(), neighbour.begin(), neighbour.end());
  EXPECT_NE(mesh_error(two_cubes).find("not a 2-manifold"), std::string::npos)
      << mesh_error(two_cubes);

  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_NE(mesh_error({{{a, b, c}}, {{a, c, b}}}).find("no volume"), std::string::npos);
  EXPECT_NE(mesh_error({}).find("no triangle"), std::string::npos);
}

}  // namespace
}  // namespace partimix::geometry
