// The box contact surfaces (geometry/box_container_surface.hpp, solid_box_surface.hpp;
// docs/dem.md, "Walls"): the inside of a tank with an open top, and the outside of a plate,
// against points whose answer is known by construction, to 1e-12.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/box_container_surface.hpp"
#include "geometry/solid_box_surface.hpp"
#include "surface_expectations.hpp"

namespace partimix::geometry {
namespace {

using testing::expect_contact;
using testing::expect_no_contact;

// [0, 1] x [0, 2] x [0, 3], open at the top (z = 3).
BoxContainerSurface open_tank() {
  return BoxContainerSurface(Vec3::Zero(), Vec3(1.0, 2.0, 3.0), {Face{2, 1}});
}

TEST(BoxContainerSurface, InsideTheNearestClosedFaceWithItsInwardNormal) {
  const BoxContainerSurface tank = open_tank();
  expect_contact(tank, Vec3(0.1, 1.0, 1.5), 1.0, Vec3(0.0, 1.0, 1.5), Vec3::UnitX(), 0.1);
  expect_contact(tank, Vec3(0.5, 1.96, 1.5), 1.0, Vec3(0.5, 2.0, 1.5), -Vec3::UnitY(), 0.04);
  expect_contact(tank, Vec3(0.5, 1.0, 0.02), 1.0, Vec3(0.5, 1.0, 0.0), Vec3::UnitZ(), 0.02);
  // Near a closed edge, inside: the nearer face only.
  expect_contact(tank, Vec3(0.1, 0.05, 1.5), 1.0, Vec3(0.1, 0.0, 1.5), Vec3::UnitY(), 0.05);
}

TEST(BoxContainerSurface, TheOpenFaceIsNotASurface) {
  const BoxContainerSurface tank = open_tank();
  // Just below the open top the nearest closed face is the wall x = 0, 0.3 away.
  expect_contact(tank, Vec3(0.3, 1.0, 2.99), 1.0, Vec3(0.0, 1.0, 2.99), Vec3::UnitX(), 0.3);
  // Above the opening, farther than the reach from every rim: nothing.
  expect_no_contact(tank, Vec3(0.5, 1.0, 3.2), 0.3);
}

TEST(BoxContainerSurface, RimsOfTheOpeningAreTouchedFromEitherSide) {
  const BoxContainerSurface tank = open_tank();
  const double h = std::sqrt(0.5);
  expect_contact(tank, Vec3(0.05, 1.0, 3.05), 0.1, Vec3(0.0, 1.0, 3.0), Vec3(h, 0.0, h),
                 0.05 * std::sqrt(2.0));
  // From outside the tank, over the rim of the wall x = 0.
  expect_contact(tank, Vec3(-0.03, 1.0, 3.04), 0.1, Vec3(0.0, 1.0, 3.0), Vec3(-0.6, 0.0, 0.8),
                 0.05);
}

TEST(BoxContainerSurface, ACentreThatCrossedAClosedFaceHasANegativeGap) {
  const BoxContainerSurface tank = open_tank();
  expect_contact(tank, Vec3(0.5, 1.0, -0.02), 0.01, Vec3(0.5, 1.0, 0.0), Vec3::UnitZ(), -0.02);
  expect_contact(tank, Vec3(1.5, 1.0, 1.5), 0.01, Vec3(1.0, 1.0, 1.5), -Vec3::UnitX(), -0.5);
  // Across an edge and a corner of closed faces: the normal points back inside.
  expect_contact(tank, Vec3(-0.03, 1.0, -0.04), 0.01, Vec3(0.0, 1.0, 0.0), Vec3(0.6, 0.0, 0.8),
                 -0.05);
  expect_contact(tank, Vec3(-0.01, -0.02, -0.02), 0.01, Vec3::Zero(), Vec3(1.0, 2.0, 2.0) / 3.0,
                 -0.03);
}

TEST(BoxContainerSurface, ReachCutsOffOnTheMaterialSideOnly) {
  const BoxContainerSurface tank = open_tank();
  expect_no_contact(tank, Vec3(0.5, 1.0, 1.5), 0.4);
  expect_contact(tank, Vec3(0.5, 1.0, 1.5), 0.5, Vec3(0.0, 1.0, 1.5), Vec3::UnitX(), 0.5);
  const BoxContainerSurface all_open(
      Vec3::Zero(), Vec3::Ones(),
      {Face{0, -1}, Face{0, 1}, Face{1, -1}, Face{1, 1}, Face{2, -1}, Face{2, 1}});
  expect_no_contact(all_open, Vec3(0.5, 0.5, 0.01), 1.0);
}

// A plate 1 x 1 x 0.1.
SolidBoxSurface plate() {
  return SolidBoxSurface(Vec3::Zero(), Vec3(1.0, 1.0, 0.1));
}

TEST(SolidBoxSurface, FaceEdgeAndCornerWithOutwardNormals) {
  const SolidBoxSurface box = plate();
  expect_contact(box, Vec3(0.5, 0.5, 0.15), 0.1, Vec3(0.5, 0.5, 0.1), Vec3::UnitZ(), 0.05);
  expect_contact(box, Vec3(1.03, 0.5, 0.14), 0.1, Vec3(1.0, 0.5, 0.1), Vec3(0.6, 0.0, 0.8), 0.05);
  expect_contact(box, Vec3(-0.01, -0.02, -0.02), 0.1, Vec3::Zero(), -Vec3(1.0, 2.0, 2.0) / 3.0,
                 0.03);
}

TEST(SolidBoxSurface, ACentreInsideTouchesTheNearestFaceWithANegativeGap) {
  const SolidBoxSurface box = plate();
  expect_contact(box, Vec3(0.5, 0.5, 0.03), 0.1, Vec3(0.5, 0.5, 0.0), -Vec3::UnitZ(), -0.03);
  expect_contact(box, Vec3(0.98, 0.5, 0.05), 0.1, Vec3(1.0, 0.5, 0.05), Vec3::UnitX(), -0.02);
  // On the surface: gap 0 with the face's normal.
  expect_contact(box, Vec3(0.5, 0.0, 0.05), 0.1, Vec3(0.5, 0.0, 0.05), -Vec3::UnitY(), 0.0);
}

TEST(SolidBoxSurface, ReachCutsOff) {
  expect_no_contact(plate(), Vec3(0.5, 0.5, 0.5), 0.3);
}

}  // namespace
}  // namespace partimix::geometry
