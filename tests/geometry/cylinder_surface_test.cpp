// The cylinder contact surfaces (geometry/cylinder_vessel_surface.hpp,
// solid_cylinder_surface.hpp; docs/dem.md, "Walls"): the inside of a vessel with an open top,
// and the outside of a shaft, against points whose answer is known by construction, to 1e-12.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/cylinder_vessel_surface.hpp"
#include "geometry/solid_cylinder_surface.hpp"
#include "surface_expectations.hpp"

namespace partimix::geometry {
namespace {

using testing::expect_contact;
using testing::expect_no_contact;

// Radius 1, height 2, base at (0, 0, 0), open at the top.
CylinderVesselSurface open_vessel() {
  return CylinderVesselSurface(Vec3::Zero(), 1.0, 2.0, {Face{2, 1}});
}

TEST(CylinderVesselSurface, SideAndBottomWithInwardNormals) {
  const CylinderVesselSurface vessel = open_vessel();
  expect_contact(vessel, Vec3(0.9, 0.0, 1.0), 0.5, Vec3(1.0, 0.0, 1.0), -Vec3::UnitX(), 0.1);
  expect_contact(vessel, Vec3(0.0, -0.95, 1.2), 0.5, Vec3(0.0, -1.0, 1.2), Vec3::UnitY(), 0.05);
  const Vec3 e = Vec3(0.6, 0.8, 0.0);
  expect_contact(vessel, 0.9 * e + Vec3(0.0, 0.0, 0.5), 0.5, e + Vec3(0.0, 0.0, 0.5), -e, 0.1);
  expect_contact(vessel, Vec3(0.3, 0.4, 0.05), 0.5, Vec3(0.3, 0.4, 0.0), Vec3::UnitZ(), 0.05);
  // Inside near the bottom corner: the nearer of side and bottom.
  expect_contact(vessel, Vec3(0.0, 0.97, 0.05), 0.5, Vec3(0.0, 1.0, 0.05), -Vec3::UnitY(), 0.03);
}

TEST(CylinderVesselSurface, ACentreThatCrossedHasANegativeGap) {
  const CylinderVesselSurface vessel = open_vessel();
  expect_contact(vessel, Vec3(0.3, 0.4, -0.02), 0.01, Vec3(0.3, 0.4, 0.0), Vec3::UnitZ(), -0.02);
  expect_contact(vessel, Vec3(1.1, 0.0, 1.0), 0.01, Vec3(1.0, 0.0, 1.0), -Vec3::UnitX(), -0.1);
  // Across the bottom rim: the normal points back inside.
  expect_contact(vessel, Vec3(1.03, 0.0, -0.04), 0.01, Vec3(1.0, 0.0, 0.0), Vec3(-0.6, 0.0, 0.8),
                 -0.05);
}

TEST(CylinderVesselSurface, TheRimOfTheOpenTopIsTouchedFromEitherSide) {
  const CylinderVesselSurface vessel = open_vessel();
  expect_contact(vessel, Vec3(0.97, 0.0, 2.04), 0.1, Vec3(1.0, 0.0, 2.0), Vec3(-0.6, 0.0, 0.8),
                 0.05);
  expect_contact(vessel, Vec3(1.03, 0.0, 2.04), 0.1, Vec3(1.0, 0.0, 2.0), Vec3(0.6, 0.0, 0.8),
                 0.05);
  // Above the opening, farther than the reach from the rim: nothing.
  expect_no_contact(vessel, Vec3(0.0, 0.0, 2.5), 0.5);
  // Just below the open top, the side.
  expect_contact(vessel, Vec3(0.0, 0.8, 1.99), 0.5, Vec3(0.0, 1.0, 1.99), -Vec3::UnitY(), 0.2);
}

TEST(CylinderVesselSurface, AClosedTopAndAnOpenBottom) {
  const CylinderVesselSurface closed(Vec3(1.0, 2.0, 3.0), 1.0, 2.0, {});
  expect_contact(closed, Vec3(1.2, 2.0, 4.96), 0.5, Vec3(1.2, 2.0, 5.0), -Vec3::UnitZ(), 0.04);
  const CylinderVesselSurface bottomless(Vec3::Zero(), 1.0, 2.0, {Face{2, -1}, Face{0, 1}});
  // Face x+ is ignored; below the open bottom only the rim is near.
  expect_no_contact(bottomless, Vec3(0.0, 0.0, -0.05), 0.5);
  expect_contact(bottomless, Vec3(0.97, 0.0, -0.04), 0.1, Vec3(1.0, 0.0, 0.0),
                 Vec3(-0.6, 0.0, -0.8), 0.05);
  expect_contact(bottomless, Vec3(0.98, 0.0, 1.0), 0.1, Vec3(1.0, 0.0, 1.0), -Vec3::UnitX(), 0.02);
}

TEST(CylinderVesselSurface, OnTheAxisTheSideIsReachedInSomeRadialDirection) {
  const CylinderVesselSurface tall(Vec3::Zero(), 1.0, 4.0, {});
  SurfacePoint s;
  ASSERT_TRUE(tall.nearest(Vec3(0.0, 0.0, 2.0), 2.0, s));
  EXPECT_NEAR(s.gap, 1.0, 1e-12);
  EXPECT_NEAR(std::hypot(s.point.x(), s.point.y()), 1.0, 1e-12);
  EXPECT_NEAR(s.point.z(), 2.0, 1e-12);
  const Vec3 radial(s.point.x(), s.point.y(), 0.0);
  EXPECT_LT((s.normal + radial).norm(), 1e-12);
  expect_no_contact(tall, Vec3(0.0, 0.0, 2.0), 0.5);
}

// A shaft: radius 0.05, from z = 0 to 1.
SolidCylinderSurface shaft() {
  return SolidCylinderSurface(Vec3::Zero(), 0.05, 1.0);
}

TEST(SolidCylinderSurface, SideDiscAndRimWithOutwardNormals) {
  const SolidCylinderSurface s = shaft();
  expect_contact(s, Vec3(0.08, 0.0, 0.5), 0.1, Vec3(0.05, 0.0, 0.5), Vec3::UnitX(), 0.03);
  expect_contact(s, Vec3(0.0, -0.06, 0.5), 0.1, Vec3(0.0, -0.05, 0.5), -Vec3::UnitY(), 0.01);
  expect_contact(s, Vec3(0.01, 0.02, 1.03), 0.1, Vec3(0.01, 0.02, 1.0), Vec3::UnitZ(), 0.03);
  expect_contact(s, Vec3(0.08, 0.0, -0.04), 0.1, Vec3(0.05, 0.0, 0.0), Vec3(0.6, 0.0, -0.8), 0.05);
}

TEST(SolidCylinderSurface, ACentreInsideTouchesTheNearestPartWithANegativeGap) {
  const SolidCylinderSurface s = shaft();
  expect_contact(s, Vec3(0.04, 0.0, 0.5), 0.1, Vec3(0.05, 0.0, 0.5), Vec3::UnitX(), -0.01);
  expect_contact(s, Vec3(0.0, 0.0, 0.98), 0.1, Vec3(0.0, 0.0, 1.0), Vec3::UnitZ(), -0.02);
  expect_contact(s, Vec3(0.01, 0.0, 0.01), 0.1, Vec3(0.01, 0.0, 0.0), -Vec3::UnitZ(), -0.01);
}

TEST(SolidCylinderSurface, ReachCutsOff) {
  expect_no_contact(shaft(), Vec3(0.2, 0.0, 0.5), 0.1);
  expect_no_contact(shaft(), Vec3(0.0, 0.0, 1.2), 0.1);
}

}  // namespace
}  // namespace partimix::geometry
