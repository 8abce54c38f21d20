// A superquadric grain against a wall (docs/dem.md, "Walls and superquadrics"): a turned
// ellipsoid on a plane against the ellipsoid's support function in closed form (1e-12); a
// sphere-shaped grain in a drum against the sphere's overlap R - gap (1e-12); a turned ellipsoid
// in a drum and a blocky grain on a plane against the deepest of 40,000 surface points
// (overlap within 2e-3 of the smallest half-axis, normal within 1e-9 rad of the wall's).
// Walls of several faces (docs/dem.md, "Walls and superquadrics"), one contact per face: a turned
// ellipsoid on a tilted flat mesh of small triangles gets the plane's one contact (1e-12), in a
// concave mesh corner and in a box container's corner the two faces' plane contacts (1e-12); a
// sphere-shaped grain in a cylinder vessel's bottom corner the side's and the bottom's overlaps
// R - gap (1e-12). Across a convex edge of a mesh, the wedge behind both faces (below).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "dem/superquadric_wall.hpp"
#include "geometry/box_container_surface.hpp"
#include "geometry/cylinder_vessel_surface.hpp"
#include "geometry/drum_surface.hpp"
#include "geometry/grid_meshes.hpp"
#include "geometry/mesh_shell_surface.hpp"
#include "geometry/plane_surface.hpp"

namespace partimix::dem {
namespace {

Mat3 turned(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(SuperquadricWall, TurnedEllipsoidOnAPlaneMatchesItsSupportFunction) {
  const Vec3 axes(1.0e-3, 2.0e-3, 3.0e-3);
  const Superquadric grain(axes, 2.0, 2.0);
  const geometry::PlaneSurface floor(Vec3::Zero(), Vec3::UnitY());
  const Mat3 q = turned(0.7, Vec3(1, 2, 3));
  const Mat3 shape = q * axes.cwiseProduct(axes).asDiagonal() * q.transpose();
  const double height = std::sqrt(Vec3::UnitY().dot(shape * Vec3::UnitY()));
  const Vec3 centre(0.01, height - 2.0e-4, -0.02);
  const WallContact contact = superquadric_face_contact(grain, centre, q, floor);
  ASSERT_TRUE(contact.touching);
  EXPECT_TRUE(contact.converged);
  EXPECT_NEAR(contact.overlap, 2.0e-4, 1e-15);
  EXPECT_LT((contact.normal - Vec3::UnitY()).norm(), 1e-15);
  const Vec3 deepest = centre - shape * Vec3::UnitY() / height;
  EXPECT_LT((contact.point - (deepest + 1.0e-4 * Vec3::UnitY())).norm(), 1e-15);
  EXPECT_FALSE(
      superquadric_face_contact(grain, centre + 3.0e-4 * Vec3::UnitY(), q, floor).touching);
}

// A convex face rejects a grain after one support point when the grain's extent along the normal
// falls short of the gap (Surface::face_is_convex): grains 1e-9 m either side of touching, turned
// at random, ellipsoids and blocky grains, over a plane and over a box container's floor, touch
// exactly when the support point says so, and the ones that touch keep the iteration's overlap.
TEST(SuperquadricWall, ConvexFacesRejectGrainsThatFallShortOfTheGap) {
  const geometry::PlaneSurface floor(Vec3::Zero(), Vec3::UnitY());
  const geometry::BoxContainerSurface box(Vec3(-0.01, 0.0, -0.01), Vec3(0.01, 0.02, 0.01),
                                          {geometry::Face{1, 1}});  // open top
  ASSERT_TRUE(floor.face_is_convex(0));
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int checked = 0;
  for (const double n1 : {2.0, 4.0}) {
    const Superquadric grain(Vec3(1.0e-3, 1.5e-3, 3.0e-3), n1, n1);
    for (int k = 0; k < 50; ++k) {
      const Mat3 q = turned(3.0 * unit(random), Vec3(unit(random), unit(random), 1.0));
      // The extent below the centre along -y: the support point in that direction.
      const double extent = -(q * grain.support(q.transpose() * -Vec3::UnitY())).y();
      for (const double miss : {-1.0e-9, 1.0e-9}) {
        const Vec3 centre(1.0e-3 * unit(random), extent + miss, 1.0e-3 * unit(random));
        const WallContact on_plane = superquadric_face_contact(grain, centre, q, floor);
        EXPECT_EQ(on_plane.touching, miss < 0.0);
        EXPECT_TRUE(on_plane.converged);
        if (on_plane.touching) {
          EXPECT_NEAR(on_plane.overlap, -miss, 1e-15);
        }
        const int bottom = 2;  // face 2 axis + (side > 0): y, low side
        ASSERT_TRUE(box.face_is_convex(bottom));
        EXPECT_EQ(superquadric_face_contact(grain, centre, q, box, bottom).touching, miss < 0.0);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 200);
}

TEST(SuperquadricWall, SphereShapedGrainInADrumOverlapsAsTheSphere) {
  const double r = 2.0e-3;
  const Superquadric grain(Vec3::Constant(r), 2.0, 2.0);
  const geometry::DrumSurface drum(Vec3::Zero(), Vec3::UnitZ(), 0.1);
  const Vec3 centre = (0.1 - r + 3.0e-4) * Vec3(0.6, -0.8, 0.0) + Vec3(0, 0, 0.01);
  const WallContact contact =
      superquadric_face_contact(grain, centre, turned(1.0, Vec3(1, 1, 0)), drum);
  ASSERT_TRUE(contact.touching);
  EXPECT_NEAR(contact.overlap, 3.0e-4, 1e-12);
  EXPECT_LT((contact.normal - Vec3(-0.6, 0.8, 0.0)).norm(), 1e-12);
}

// The deepest of many surface points (along rays from the centre, by bisection on F) into the
// wall: the largest -gap.
double deepest_sampled(const Superquadric& grain, const Vec3& centre, const Mat3& q,
                       const geometry::Surface& wall) {
  std::mt19937 random(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  double deepest = -1.0;
  for (int ray = 0; ray < 40000; ++ray) {
    const Vec3 e = Vec3(normal(random), normal(random), normal(random)).normalized();
    double inside = 0.0;
    double outside = 2.0 * grain.bounding_radius();
    for (int halving = 0; halving < 50; ++halving) {
      const double middle = 0.5 * (inside + outside);
      (grain.value(middle * e) < 0.0 ? inside : outside) = middle;
    }
    geometry::SurfacePoint at;
    if (wall.nearest(centre + q * (inside * e), 1.0, at))
      deepest = std::max(deepest, -at.gap);
  }
  return deepest;
}

TEST(SuperquadricWall, TurnedEllipsoidInADrumAndBlockyGrainOnAPlaneMatchSampledSurfaces) {
  const geometry::DrumSurface drum(Vec3::Zero(), Vec3::UnitZ(), 0.02);
  const Superquadric ellipsoid(Vec3(1.0e-3, 1.0e-3, 3.0e-3), 2.0, 2.0);
  const Mat3 q = turned(0.9, Vec3(1, -2, 0.5));
  const Vec3 centre(0.0, -0.0186, 0.0);
  const WallContact in_drum = superquadric_face_contact(ellipsoid, centre, q, drum);
  ASSERT_TRUE(in_drum.touching);
  EXPECT_TRUE(in_drum.converged);
  EXPECT_NEAR(in_drum.overlap, deepest_sampled(ellipsoid, centre, q, drum), 2e-6);

  const geometry::PlaneSurface floor(Vec3::Zero(), Vec3(0.2, 1.0, 0.1));
  const Superquadric blocky(Vec3(1.0e-3, 1.5e-3, 2.0e-3), 6.0, 4.0);
  const Mat3 tilt = turned(0.4, Vec3(2, 1, -1));
  const Vec3 up = Vec3(0.2, 1.0, 0.1).normalized();
  const Vec3 above = 1.5e-3 * up;
  const WallContact on_floor = superquadric_face_contact(blocky, above, tilt, floor);
  ASSERT_TRUE(on_floor.touching);
  EXPECT_NEAR(on_floor.overlap, deepest_sampled(blocky, above, tilt, floor), 2e-6);
  EXPECT_LT((on_floor.normal - up).norm(), 1e-9);
}

struct Expected {
  Vec3 normal;
  double overlap;
};

// The contacts of the grain with every face of `wall` are `expected`, deepest first, none failing.
void expect_contacts(const Superquadric& grain, const Vec3& centre, const Mat3& q,
                     const geometry::Surface& wall, const std::vector<Expected>& expected) {
  std::array<WallContact, 8> found;
  int failures = 0;
  const int count = superquadric_wall_contacts(grain, centre, q, wall, found, failures);
  EXPECT_EQ(failures, 0);
  ASSERT_EQ(count, static_cast<int>(expected.size())) << "centre " << centre.transpose();
  for (int k = 0; k < count; ++k) {
    EXPECT_NEAR(found[k].overlap, expected[k].overlap, 1e-12) << "contact " << k;
    EXPECT_LT((found[k].normal - expected[k].normal).norm(), 1e-12) << "contact " << k;
  }
}

// The depth of the grain below the plane through `point` with unit normal `up`.
double plane_overlap(const Superquadric& grain, const Vec3& centre, const Mat3& q,
                     const Vec3& point, const Vec3& up) {
  return -(centre + q * grain.support(q.transpose() * -up) - point).dot(up);
}

TEST(SuperquadricWall, AnEllipsoidMeetsEachFaceOfAMeshAndABoxOnce) {
  const Superquadric ellipsoid(Vec3(1.0e-3, 1.5e-3, 3.0e-3), 2.0, 2.0);
  const Mat3 q = turned(0.8, Vec3(1, 2, 3));
  const Mat3 tilt = turned(0.3, Vec3(1, -1, 0.5));
  const Vec3 up = tilt.col(2);
  geometry::TriangleSoup flat;
  geometry::testing::add_patch(flat, Vec3(-0.01, -0.01, 0.0), 5e-4 * tilt.col(0),
                               5e-4 * tilt.col(1), 40, 40);
  const geometry::MeshShellSurface mesh(flat);
  const Vec3 origin = Vec3(-0.01, -0.01, 0.0) + 0.01 * (tilt.col(0) + tilt.col(1));
  const double height = ellipsoid.support(q.transpose() * -up).dot(q.transpose() * -up);
  const Vec3 centre = origin + (height - 2e-4) * up;
  expect_contacts(ellipsoid, centre, q, mesh, {{up, 2e-4}});

  const geometry::MeshShellSurface corner(geometry::testing::corner_mesh(5e-4, 20));
  const geometry::BoxContainerSurface box(Vec3(0.0, -0.01, 0.0), Vec3::Constant(0.01), {});
  const Vec3 in_corner(
      plane_overlap(ellipsoid, Vec3::Zero(), q, Vec3::Zero(), Vec3::UnitX()) - 1e-4, 1e-4,
      plane_overlap(ellipsoid, Vec3::Zero(), q, Vec3::Zero(), Vec3::UnitZ()) - 2e-4);
  const std::vector<Expected> both{{Vec3::UnitZ(), 2e-4}, {Vec3::UnitX(), 1e-4}};
  expect_contacts(ellipsoid, in_corner, q, corner, both);
  expect_contacts(ellipsoid, in_corner, q, box, both);
}

TEST(SuperquadricWall, ASphereShapedGrainInAVesselCornerOverlapsSideAndBottom) {
  const Superquadric sphere(Vec3::Constant(1e-3), 2.0, 2.0);
  const geometry::CylinderVesselSurface vessel(Vec3::Zero(), 0.01, 0.02, {});
  expect_contacts(sphere, Vec3(0.0, 0.0092, 0.0007), turned(0.5, Vec3(1, 1, 1)), vessel,
                  {{Vec3::UnitZ(), 3e-4}, {-Vec3::UnitY(), 2e-4}});
}

// The grain's overlap with the wedge under the roof along the unit normal at `angle` from the
// left part's normal towards the right's, and its least over the cone: the least of `samples`
// angles, then a golden-section search between that sample's neighbours (the overlap is convex
// in the angle near its least, and can be sharp there: a blocky grain's flat face has an
// unbounded radius of curvature).
double wedge_overlap(const Superquadric& grain, const Vec3& centre, const Mat3& q, double slope,
                     double angle) {
  const double tilt = -slope + angle;
  const Vec3 m(0.0, std::sin(tilt), std::cos(tilt));
  return -(centre + q * grain.support(q.transpose() * -m)).dot(m);
}

double least_wedge_overlap(const Superquadric& grain, const Vec3& centre, const Mat3& q,
                           double slope, int samples) {
  const double step = 2.0 * slope / samples;
  const auto overlap_at = [&](double angle) {
    return wedge_overlap(grain, centre, q, slope, std::clamp(angle, 0.0, 2.0 * slope));
  };
  int best = 0;
  for (int k = 1; k <= samples; ++k)
    best = overlap_at(k * step) < overlap_at(best * step) ? k : best;
  double low = (best - 1) * step;
  double high = (best + 1) * step;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 100; ++k) {
    const double left = high - golden * (high - low);
    const double right = low + golden * (high - low);
    if (overlap_at(left) < overlap_at(right))
      high = right;
    else
      low = left;
  }
  return std::min(overlap_at(best * step), overlap_at(0.5 * (low + high)));
}

// Across a convex edge the wall is the wedge behind its two faces (docs/dem.md, "Walls and
// superquadrics", Convex edges). An ellipsoid standing on its tip on the ridge (the failure
// noted before: one contact 70 degrees off the vertical with 1.75 times the overlap) gets one
// contact, vertical, with the tip's depth (1e-12); turned ellipsoids and blocky grains near the
// ridge get one contact or none, as the least overlap over the normals of the cone says (2001
// samples refined by a golden-section search), with that overlap (1e-15 m; measured 1e-18 over
// 63 touching grains, 35 with the least at an end of the cone, 28 inside it), and no failure.
TEST(SuperquadricWall, AGrainOnAConvexRidgeMeetsTheWedgeBehindBothFaces) {
  const double slope = 0.5;
  const geometry::MeshShellSurface roof(geometry::testing::roof_mesh(slope, 5e-4, 20));
  const Superquadric standing(Vec3(1.0e-3, 1.5e-3, 3.0e-3), 2.0, 2.0);
  expect_contacts(standing, Vec3(0.0, 0.0, 3.0e-3 - 1.0e-4), Mat3::Identity(), roof,
                  {{Vec3::UnitZ(), 1.0e-4}});

  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int touching = 0;
  for (const double n1 : {2.0, 4.0}) {
    const Superquadric grain(Vec3(1.0e-3, 1.5e-3, 3.0e-3), n1, n1 + 2.0);
    for (int k = 0; k < 40; ++k) {
      const Mat3 q = turned(3.0 * unit(random), Vec3(unit(random), unit(random), unit(random)));
      Vec3 centre(1.0e-3 * unit(random), 1.0e-3 * unit(random), 0.0);
      centre.z() = 3.0e-4 * unit(random) + least_wedge_overlap(grain, centre, q, slope, 2000);
      const double least = least_wedge_overlap(grain, centre, q, slope, 2000);
      std::array<WallContact, 8> found;
      int failures = 0;
      const int count = superquadric_wall_contacts(grain, centre, q, roof, found, failures);
      EXPECT_EQ(failures, 0);
      ASSERT_EQ(count, least > 0.0 ? 1 : 0) << "least overlap " << least;
      if (count == 1) {
        ++touching;
        EXPECT_NEAR(found[0].overlap, least, 1e-15);
      }
    }
  }
  EXPECT_GT(touching, 20);
}

}  // namespace
}  // namespace partimix::dem
