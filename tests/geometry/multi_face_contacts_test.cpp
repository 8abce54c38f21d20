// Contacts of a sphere with walls of several faces (docs/dem.md, "Walls of several faces"),
// against the analytical nearest points, to 1e-12:
// - a flat, tilted mesh of many small triangles: a sphere over a vertex of six triangles, over an
//   edge, over a diagonal, inside a face, gets one contact: the plane's gap and normal; also
//   where more triangles lie within reach than the mesh looks at (64);
// - a convex ridge of a mesh: one contact, from the ridge; beside it, the face's;
// - a concave 90-degree corner of a mesh: two, one per face;
// - a box container: three in a corner, one per face; at its open top one per rim it touches
//   (two in a corner of the opening, one outside it);
// - a cylinder vessel: the side and the bottom in the corner between them;
// - a plane: its nearest point, as face 0.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "geometry/box_container_surface.hpp"
#include "geometry/cylinder_vessel_surface.hpp"
#include "geometry/grid_meshes.hpp"
#include "geometry/mesh_shell_surface.hpp"
#include "geometry/plane_surface.hpp"

namespace partimix::geometry {
namespace {

using testing::add_patch;
using testing::corner_mesh;

constexpr double kTolerance = 1e-12;

struct Expected {
  Vec3 point;
  Vec3 normal;
  double gap;
};

// The contacts within `reach` of `centre` are `expected`, deepest first.
void expect_contacts(const Surface& surface, const Vec3& centre, double reach,
                     const std::vector<Expected>& expected) {
  std::array<SurfacePoint, kMaxSurfaceContacts> found;
  const int count = surface.contacts(centre, reach, found);
  ASSERT_EQ(count, static_cast<int>(expected.size())) << "centre " << centre.transpose();
  for (int k = 0; k < count; ++k) {
    EXPECT_NEAR(found[k].gap, expected[k].gap, kTolerance) << "contact " << k;
    EXPECT_LT((found[k].normal - expected[k].normal).norm(), kTolerance)
        << "contact " << k << " normal " << found[k].normal.transpose();
    EXPECT_LT((found[k].point - expected[k].point).norm(), kTolerance)
        << "contact " << k << " point " << found[k].point.transpose();
  }
}

TEST(MultiFaceContacts, ASphereOnAFlatMeshOfManyTrianglesGetsThePlanesContactOnce) {
  const Mat3 tilt = Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  const Vec3 origin(0.3, -0.2, 0.1);
  const Vec3 normal = tilt.col(2);
  for (const double cell : {0.5, 0.2}) {  // 16 and about 100 triangles within reach
    const Vec3 u = cell * tilt.col(0);
    const Vec3 v = cell * tilt.col(1);
    TriangleSoup soup;
    add_patch(soup, origin, u, v, 40, 40);
    const MeshShellSurface mesh(soup);
    const Vec3 middle = origin + 20.0 * (u + v);
    for (const Vec3& at : {middle, Vec3(middle + 0.5 * v), Vec3(middle + 0.5 * (u + v)),
                           Vec3(middle + 0.7 * u + 0.2 * v)}) {
      for (const double side : {1.0, -1.0})
        expect_contacts(mesh, at + side * 0.6 * normal, 1.0, {{at, side * normal, 0.6}});
    }
  }
}

TEST(MultiFaceContacts, ASphereOnAConvexRidgeGetsOneContactFromTheRidge) {
  const double cell = 0.25;
  const double slope = 0.5;
  TriangleSoup soup;
  const Vec3 origin(0.0, -4.0, 0.0);
  add_patch(soup, origin, cell * Vec3(1.0, 0.0, -slope), cell * Vec3::UnitY(), 16, 32);
  add_patch(soup, origin, cell * Vec3(-1.0, 0.0, -slope), cell * Vec3::UnitY(), 16, 32);
  const MeshShellSurface roof(soup);
  for (const double y : {0.0, 0.125})
    expect_contacts(roof, Vec3(0.0, y, 0.6), 1.0, {{Vec3(0.0, y, 0.0), Vec3::UnitZ(), 0.6}});
  const Vec3 face_normal = Vec3(slope, 0.0, 1.0).normalized();
  const Vec3 on_face(1.2, 0.3, -slope * 1.2);
  expect_contacts(roof, on_face + 0.6 * face_normal, 1.0, {{on_face, face_normal, 0.6}});
}

TEST(MultiFaceContacts, ASphereInAConcaveMeshCornerGetsOneContactPerFace) {
  const MeshShellSurface corner(corner_mesh(0.25, 8));
  expect_contacts(
      corner, Vec3(0.6, 0.5, 0.7), 1.0,
      {{Vec3(0.0, 0.5, 0.7), Vec3::UnitX(), 0.6}, {Vec3(0.6, 0.5, 0.0), Vec3::UnitZ(), 0.7}});
}

TEST(MultiFaceContacts, ABoxContainerGivesOneContactPerFaceAndPerRim) {
  const BoxContainerSurface box(Vec3::Zero(), Vec3::Ones(), {Face{2, 1}});
  expect_contacts(box, Vec3(0.2, 0.3, 0.25), 0.35,
                  {{Vec3(0.0, 0.3, 0.25), Vec3::UnitX(), 0.2},
                   {Vec3(0.2, 0.3, 0.0), Vec3::UnitZ(), 0.25},
                   {Vec3(0.2, 0.0, 0.25), Vec3::UnitY(), 0.3}});
  expect_contacts(box, Vec3(0.2, 0.3, 0.25), 0.22, {{Vec3(0.0, 0.3, 0.25), Vec3::UnitX(), 0.2}});
  const double rim = std::hypot(0.1, 0.05);
  const Vec3 up_x = Vec3(0.1, 0.0, 0.05) / rim;
  const Vec3 up_y = Vec3(0.0, 0.1, 0.05) / rim;
  expect_contacts(box, Vec3(0.5, 0.1, 1.05), 0.2, {{Vec3(0.5, 0.0, 1.0), up_y, rim}});
  expect_contacts(box, Vec3(0.1, 0.1, 1.05), 0.2,
                  {{Vec3(0.0, 0.1, 1.0), up_x, rim}, {Vec3(0.1, 0.0, 1.0), up_y, rim}});
  const Vec3 outside(-0.1, -0.05, 1.05);
  const Vec3 corner(0.0, 0.0, 1.0);
  expect_contacts(box, outside, 0.2,
                  {{corner, (outside - corner).normalized(), (outside - corner).norm()}});
}

TEST(MultiFaceContacts, ACylinderVesselGivesTheSideAndTheBottomInTheirCorner) {
  const CylinderVesselSurface vessel(Vec3::Zero(), 1.0, 2.0, {});
  expect_contacts(
      vessel, Vec3(0.0, 0.85, 0.1), 0.2,
      {{Vec3(0.0, 0.85, 0.0), Vec3::UnitZ(), 0.1}, {Vec3(0.0, 1.0, 0.1), -Vec3::UnitY(), 0.15}});
}

TEST(MultiFaceContacts, APlaneGivesItsNearestPointAsFaceZero) {
  const PlaneSurface plane(Vec3::Zero(), Vec3::UnitZ());
  expect_contacts(plane, Vec3(1.0, 2.0, 0.3), 0.5, {{Vec3(1.0, 2.0, 0.0), Vec3::UnitZ(), 0.3}});
  std::array<SurfacePoint, 1> one;
  ASSERT_EQ(plane.contacts(Vec3(1.0, 2.0, 0.3), 0.5, one), 1);
  EXPECT_EQ(one[0].face, 0);
  EXPECT_EQ(plane.contacts(Vec3(1.0, 2.0, 0.6), 0.5, one), 0);
}

}  // namespace
}  // namespace partimix::geometry
