// The layers of a solid body (docs/geometry-meshes.md, "Solid walls"): lattice points inside the
// shape within `layers` spacings of its surface, on the lattice of fill(); a plate thinner than
// the layers gets every inside point.
#include <gtest/gtest.h>

#include "geometry/lattice.hpp"

namespace partimix::geometry {
namespace {

Domain domain(int dimensions) {
  Domain d;
  d.dimensions = dimensions;
  d.lo = Vec3(-1.0, -1.0, dimensions == 3 ? -1.0 : 0.0);
  d.hi = Vec3(2.0, 2.0, dimensions == 3 ? 2.0 : 0.0);
  return d;
}

TEST(InsideLayers, BoxIn3DKeepsTheOuterShellOfItsFill) {
  const double dp = 0.1;
  const Box box(Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.6, 0.4));
  const auto points = inside_layers(box, dp, 1, domain(3));
  // The 10 x 6 x 4 fill less its core of 8 x 4 x 2 points farther than one spacing inside.
  EXPECT_EQ(points.size(), 10u * 6u * 4u - 8u * 4u * 2u);
  for (const Vec3& x : points) {
    EXPECT_LE(box.signed_distance(x), 0.0);
    EXPECT_GT(box.signed_distance(x), -dp);
  }
}

TEST(InsideLayers, RectangleIn2DKeepsTwoLayers) {
  const double dp = 0.1;
  const Box box(Vec3(0.0, 0.0, -1.0), Vec3(1.0, 0.5, 1.0));
  const auto points = inside_layers(box, dp, 2, domain(2));
  // The 10 x 5 fill less its core of 6 x 1 points farther than two spacings inside.
  EXPECT_EQ(points.size(), 10u * 5u - 6u * 1u);
  for (const Vec3& x : points) {
    EXPECT_LE(box.signed_distance(x), 0.0);
    EXPECT_GT(box.signed_distance(x), -2.0 * dp);
    EXPECT_EQ(x.z(), 0.0);
  }
}

TEST(InsideLayers, ThinPlateGetsEveryInsidePoint) {
  const Box plate(Vec3(0.0, 0.0, 0.0), Vec3(0.6, 0.03, 0.3));
  const auto points = inside_layers(plate, 0.01, 3, domain(3));
  EXPECT_EQ(points.size(), 60u * 3u * 30u);
  EXPECT_EQ(points, fill(plate, 0.01, domain(3)));
}

}  // namespace
}  // namespace partimix::geometry
