// Every shape and the contact surface it makes (Shape::make_surface) agree near the surface's
// closed parts, so that SPH (laying particles from the signed distance) and DEM (contacting the
// surface) see the same wall: for seeded random points within 0.05 of the surface, on either
// side, |gap| = |signed distance| (gap = -signed distance for a container, +signed distance for
// a solid, the distance for the two-sided mesh shell), the point lies on the shape's surface,
// and centre = point + gap normal, all to 1e-12.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "geometry/cone.hpp"
#include "geometry/drum.hpp"
#include "geometry/plane.hpp"
#include "geometry/shape.hpp"
#include "geometry/triangle_mesh.hpp"

namespace partimix::geometry {
namespace {

constexpr double kTolerance = 1e-12;
constexpr double kNear = 0.05;  // the points' largest distance from the surface
constexpr int kPoints = 400;    // per case

enum class Side { container, solid, two_sided };

struct Case {
  std::string name;
  const Shape& shape;
  Side side;
  bool solid = false;
  std::vector<Face> open_faces;
  Vec3 sample_lo;  // points are drawn uniformly in this box
  Vec3 sample_hi;
  std::function<bool(const Vec3&)> on_closed_part = [](const Vec3&) { return true; };
};

double expected_gap(Side side, double signed_distance) {
  switch (side) {
    case Side::container:
      return -signed_distance;
    case Side::solid:
      return signed_distance;
    case Side::two_sided:
      break;
  }
  return std::abs(signed_distance);
}

void check_agreement(const Case& c, std::uint64_t seed) {
  SCOPED_TRACE(c.name);
  const auto surface = c.shape.make_surface(c.solid, c.open_faces);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  int on_material_side = 0;
  for (long attempt = 0; attempt < 200000 && checked < kPoints; ++attempt) {
    const Vec3 u(unit(random), unit(random), unit(random));
    const Vec3 x = c.sample_lo + u.cwiseProduct(c.sample_hi - c.sample_lo);
    const double d = c.shape.signed_distance(x);
    if (!(std::abs(d) > 0.0 && std::abs(d) < kNear) || !c.on_closed_part(x))
      continue;
    ++checked;
    SurfacePoint s;
    ASSERT_TRUE(surface->nearest(x, 1.0, s)) << x.transpose();
    EXPECT_NEAR(s.gap, expected_gap(c.side, d), kTolerance) << x.transpose();
    EXPECT_NEAR(c.shape.signed_distance(s.point), 0.0, kTolerance) << x.transpose();
    EXPECT_NEAR(s.normal.norm(), 1.0, kTolerance) << x.transpose();
    EXPECT_LT((s.point + s.gap * s.normal - x).norm(), kTolerance) << x.transpose();
    on_material_side += s.gap > 0.0 ? 1 : 0;
  }
  EXPECT_EQ(checked, kPoints);
  // Both sides were visited (the shell has only one).
  EXPECT_GT(on_material_side, 0);
  if (c.side != Side::two_sided) {
    EXPECT_LT(on_material_side, checked);
  }
}

const Vec3 kNearMargin = Vec3::Constant(2.0 * kNear);

TEST(ShapeSurfaceAgreement, Boxes) {
  const Box box(Vec3(0.1, -0.2, 0.3), Vec3(1.1, 0.4, 0.7));
  const Vec3 lo = box.lower() - kNearMargin;
  const Vec3 hi = box.upper() + kNearMargin;
  check_agreement({"closed tank", box, Side::container, false, {}, lo, hi}, 1);
  // Away from the open top, whose rim the tank's surface treats as open.
  check_agreement({"open tank",
                   box,
                   Side::container,
                   false,
                   {Face{2, 1}},
                   lo,
                   hi,
                   [](const Vec3& x) { return x.z() < 0.7 - kNear; }},
                  2);
  check_agreement({"plate", box, Side::solid, true, {}, lo, hi}, 3);
}

TEST(ShapeSurfaceAgreement, Cylinders) {
  const Cylinder cylinder(Vec3(0.2, -0.1, 0.3), 0.4, 0.9);
  const Vec3 lo = cylinder.lower() - kNearMargin;
  const Vec3 hi = cylinder.upper() + kNearMargin;
  check_agreement({"closed vessel", cylinder, Side::container, false, {}, lo, hi}, 4);
  check_agreement({"open vessel",
                   cylinder,
                   Side::container,
                   false,
                   {Face{2, 1}},
                   lo,
                   hi,
                   [](const Vec3& x) { return x.z() < 1.2 - kNear; }},
                  5);
  check_agreement({"shaft", cylinder, Side::solid, true, {}, lo, hi}, 6);
}

TEST(ShapeSurfaceAgreement, PlaneDrumAndCone) {
  const Plane plane(Vec3(0.1, 0.2, 0.3), Vec3(1.0, -2.0, 0.5));
  check_agreement(
      {"plane", plane, Side::solid, true, {}, Vec3::Constant(-0.3), Vec3::Constant(0.7)}, 7);
  const Drum drum(Vec3(0.1, 0.2, 0.3), Vec3(1.0, 0.5, -0.3), 0.3);
  check_agreement(
      {"drum", drum, Side::container, false, {}, Vec3::Constant(-0.4), Vec3::Constant(0.8)}, 8);
  const Vec3 base(0.1, 0.2, 0.3);
  const Vec3 axis = Vec3(0.3, -1.0, 0.6).normalized();
  const double height = 0.5;
  const Cone cone(base, Vec3(0.3, -1.0, 0.6), 0.15, 0.35, height);
  // Between the open rims, where the lateral surface is the nearest part of the frustum.
  check_agreement({"cone",
                   cone,
                   Side::container,
                   false,
                   {},
                   cone.lower() - kNearMargin,
                   cone.upper() + kNearMargin,
                   [&](const Vec3& x) {
                     const double z = (x - base).dot(axis);
                     return z > kNear && z < height - kNear;
                   }},
                  9);
}

TEST(ShapeSurfaceAgreement, Mesh) {
  // An octahedron of radius 0.5 about (0.2, 0.1, 0), corners counter-clockwise from outside.
  const Vec3 centre(0.2, 0.1, 0.0);
  const Vec3 corners[6] = {Vec3::UnitX(),  -Vec3::UnitX(), Vec3::UnitY(),
                           -Vec3::UnitY(), Vec3::UnitZ(),  -Vec3::UnitZ()};
  TriangleSoup soup;
  for (int sx : {0, 1}) {
    for (int sy : {2, 3}) {
      for (int sz : {4, 5}) {
        const Vec3 a = 0.5 * corners[sx];
        const Vec3 b = 0.5 * corners[sy];
        const Vec3 c = 0.5 * corners[sz];
        // Outward when (b - a) x (c - a) points away from the centre; the mesh checks it.
        if ((b - a).cross(c - a).dot(a + b + c) > 0.0)
          soup.push_back({{a, b, c}});
        else
          soup.push_back({{a, c, b}});
      }
    }
  }
  const TriangleMesh mesh(soup, centre);
  check_agreement({"mesh shell",
                   mesh,
                   Side::two_sided,
                   false,
                   {},
                   mesh.lower() - kNearMargin,
                   mesh.upper() + kNearMargin},
                  10);
}

}  // namespace
}  // namespace partimix::geometry
