// Convex edges of a mesh as ridges (MeshShellSurface::ridge; docs/dem.md, "Walls and
// superquadrics", Convex edges): a point on the ridge of a roof, inside a triangle's edge or at a
// corner along the ridge, is a ridge with the two parts' normals towards the grains and a face
// on each side holding the point; a cube's corner seen from outside is the cone of its three
// normals; a point inside a triangle, on a flat edge or corner, in a concave corner and on the
// roof's underside is not a ridge.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/grid_meshes.hpp"
#include "geometry/mesh_shell_surface.hpp"

namespace partimix::geometry {
namespace {

constexpr double kSlope = 0.5;
constexpr double kCell = 1e-3;

// The nearest point of `surface` to `x` (within 1 m), which must exist.
SurfacePoint nearest_point(const Surface& surface, const Vec3& x) {
  SurfacePoint at;
  EXPECT_TRUE(surface.nearest(x, 1.0, at));
  return at;
}

bool ridge_at(const Surface& surface, const Vec3& x, Ridge& ridge) {
  return surface.ridge(nearest_point(surface, x), ridge);
}

// The face `face` of `mesh` holds `point` (its nearest point to it is the point itself).
void expect_face_holds(const MeshShellSurface& mesh, int face, const Vec3& point) {
  SurfacePoint at;
  ASSERT_TRUE(mesh.nearest_on_face(face, point, 1.0, at));
  EXPECT_LT((at.point - point).norm(), 1e-12);
}

void expect_roof_ridge(const MeshShellSurface& roof, const Vec3& above, bool corner) {
  SurfacePoint at = nearest_point(roof, above);
  Ridge ridge;
  ASSERT_TRUE(roof.ridge(at, ridge));
  const Vec3 left(0.0, -std::sin(kSlope), std::cos(kSlope));
  const Vec3 right(0.0, std::sin(kSlope), std::cos(kSlope));
  ASSERT_EQ(ridge.count, 2);
  const bool from_left = (ridge.normals[0] - left).norm() < 1e-12;
  EXPECT_LT((ridge.normals[0] - (from_left ? left : right)).norm(), 1e-12);
  EXPECT_LT((ridge.normals[1] - (from_left ? right : left)).norm(), 1e-12);
  EXPECT_EQ(ridge.faces[0], at.face);
  EXPECT_NE(ridge.faces[1] / 2, ridge.faces[0] / 2);
  EXPECT_EQ((ridge.start - ridge.end).norm() == 0.0, corner);
  for (const Vec3& end : {ridge.start, ridge.end}) {
    EXPECT_LT(end.tail<2>().norm(), 1e-15);  // on the x axis
    expect_face_holds(roof, ridge.faces[0], end);
    expect_face_holds(roof, ridge.faces[1], end);
  }
}

TEST(MeshRidge, TheRidgeOfARoofIsAWedgeOfItsTwoNormals) {
  const MeshShellSurface roof(testing::roof_mesh(kSlope, kCell, 8));
  expect_roof_ridge(roof, Vec3(0.3 * kCell, 0.0, 2e-3), false);  // inside an edge
  expect_roof_ridge(roof, Vec3(kCell, 0.0, 2e-3), true);         // a corner on the ridge
  // Points of the right part, at (x, t) along the ridge and down the slope, seen from 2 mm out.
  const Vec3 down(0.0, std::cos(kSlope), -std::sin(kSlope));
  const Vec3 out(0.0, std::sin(kSlope), std::cos(kSlope));
  const auto above = [&](double x, double t) {
    return Vec3(x * kCell * Vec3::UnitX() + t * kCell * down + 2e-3 * out);
  };
  Ridge ridge;
  EXPECT_FALSE(ridge_at(roof, above(0.3, 2.5), ridge));                // inside a triangle
  EXPECT_FALSE(ridge_at(roof, above(0.5, 3.0), ridge));                // on a flat edge
  EXPECT_FALSE(ridge_at(roof, above(1.0, 3.0), ridge));                // at a flat corner
  EXPECT_FALSE(ridge_at(roof, Vec3(0.3 * kCell, 0.0, -2e-3), ridge));  // underneath: concave
}

TEST(MeshRidge, ACubesCornerSeenFromOutsideIsAConeOfItsThreeNormals) {
  const MeshShellSurface cube(testing::cube_mesh(4.0 * kCell, 4));
  const Vec3 corner = 4.0 * kCell * Vec3::Ones();
  const SurfacePoint at = nearest_point(cube, Vec3(5.0, 5.0, 5.0) * kCell);
  Ridge ridge;
  ASSERT_TRUE(cube.ridge(at, ridge));
  ASSERT_EQ(ridge.count, 3);
  EXPECT_EQ(ridge.faces[0], at.face);
  EXPECT_LT((ridge.start - corner).norm(), 1e-15);
  EXPECT_LT((ridge.end - corner).norm(), 1e-15);
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(ridge.normals[k].maxCoeff(), 1.0, 1e-12);  // +x, +y or +z
    sum += ridge.normals[k];
    expect_face_holds(cube, ridge.faces[k], corner);
  }
  EXPECT_LT((sum - Vec3::Ones()).norm(), 1e-12);
  ASSERT_TRUE(ridge_at(cube, Vec3(5.0, 5.0, 0.5) * kCell, ridge));  // an edge
  EXPECT_EQ(ridge.count, 2);
}

TEST(MeshRidge, ConcaveCornersAreNoRidges) {
  Ridge ridge;
  const MeshShellSurface corner(testing::corner_mesh(kCell, 8));
  EXPECT_FALSE(ridge_at(corner, Vec3(2e-3, 0.3 * kCell, 2e-3), ridge));
}

}  // namespace
}  // namespace partimix::geometry
