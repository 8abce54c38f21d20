// A superquadric grain at a convex corner of three faces (docs/dem.md, "Walls and superquadrics",
// Convex edges and corners): near the corner of a mesh cube seen from outside the wall is the
// solid behind the three faces, and a convex grain meets it in one contact whose overlap is the
// least over the corner's cone of normals (the positive octant). Ellipsoids and blocky grains,
// turned at random, placed near the corner: one contact exactly when the reference's least is
// positive, with that overlap to 1e-12 m and a normal in the octant, and no detection failure.
// The reference shares only the support point with the code: a 40 x 40 sampling of the octant in
// spherical angles refined by a compass search.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "dem/superquadric_wall.hpp"
#include "geometry/grid_meshes.hpp"
#include "geometry/mesh_shell_surface.hpp"

namespace partimix::dem {
namespace {

constexpr double kHalf = 0.02;  // the cube's half side [m]: large against the grains

struct Placed {
  const Superquadric& grain;
  Vec3 centre;
  Mat3 rotation;
};

// The grain's overlap with the half-space behind the plane through the corner with unit normal
// at polar angle theta from z and azimuth phi from x.
double octant_overlap(const Placed& placed, double theta, double phi) {
  const Vec3 m(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  const Vec3 deepest =
      placed.centre + placed.rotation * placed.grain.support(placed.rotation.transpose() * -m);
  return m.dot(Vec3::Constant(kHalf) - deepest);
}

// The least overlap over the octant: the best of 41 x 41 angles, then a compass search from it
// whose step halves whenever no neighbour is lower, to 1e-14 rad.
double least_overlap(const Placed& placed) {
  constexpr double kQuarter = 0.5 * std::numbers::pi;
  constexpr int kSamples = 40;
  const auto overlap = [&](double theta, double phi) {
    return octant_overlap(placed, std::clamp(theta, 0.0, kQuarter), std::clamp(phi, 0.0, kQuarter));
  };
  double theta = 0.0;
  double phi = 0.0;
  double least = std::numeric_limits<double>::infinity();
  for (int a = 0; a <= kSamples; ++a) {
    for (int b = 0; b <= kSamples; ++b) {
      const double value = overlap(kQuarter * a / kSamples, kQuarter * b / kSamples);
      if (value < least) {
        least = value;
        theta = kQuarter * a / kSamples;
        phi = kQuarter * b / kSamples;
      }
    }
  }
  for (double step = kQuarter / kSamples; step > 1e-14;) {
    bool moved = false;
    for (const auto& [dt, dp] : {std::pair{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}}) {
      const double value = overlap(theta + dt * step, phi + dp * step);
      if (value < least) {
        least = value;
        theta = std::clamp(theta + dt * step, 0.0, kQuarter);
        phi = std::clamp(phi + dp * step, 0.0, kQuarter);
        moved = true;
      }
    }
    step = moved ? step : 0.5 * step;
  }
  return least;
}

// A centre on the ray from the corner along `direction` where the reference's least overlap
// (falling along the ray) is zero, found by bisection.
Vec3 touching_on_ray(const Superquadric& grain, const Mat3& rotation, const Vec3& direction) {
  double low = 0.0;
  double high = 2.0 * grain.bounding_radius();
  for (int k = 0; k < 40; ++k) {
    const double middle = 0.5 * (low + high);
    const Placed placed{grain, Vec3::Constant(kHalf) + middle * direction, rotation};
    (least_overlap(placed) > 0.0 ? low : high) = middle;
  }
  return Vec3::Constant(kHalf) + 0.5 * (low + high) * direction;
}

TEST(SuperquadricCorner, AGrainAtACubesCornerMeetsTheSolidBehindItsThreeFaces) {
  const geometry::MeshShellSurface cube(geometry::testing::cube_mesh(kHalf, 4));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int touching = 0;
  int inside_octant = 0;
  for (const double n1 : {2.0, 4.0}) {
    const Superquadric grain(Vec3(1.0e-3, 1.5e-3, 3.0e-3), n1, n1 + 2.0);
    for (int k = 0; k < 20; ++k) {
      const Mat3 rotation =
          Eigen::AngleAxisd(3.0 * unit(random),
                            Vec3(unit(random), unit(random), unit(random)).normalized())
              .toRotationMatrix();
      const Vec3 direction =
          Vec3(1.0 + 0.8 * unit(random), 1.0 + 0.8 * unit(random), 1.0 + 0.8 * unit(random))
              .normalized();
      const Vec3 centre =
          touching_on_ray(grain, rotation, direction) + 5.0e-5 * unit(random) * direction;
      const double least = least_overlap({grain, centre, rotation});
      std::array<WallContact, 8> found;
      int failures = 0;
      const int count = superquadric_wall_contacts(grain, centre, rotation, cube, found, failures);
      EXPECT_EQ(failures, 0);
      ASSERT_EQ(count, least > 0.0 ? 1 : 0) << "least overlap " << least;
      if (count == 1) {
        ++touching;
        EXPECT_NEAR(found[0].overlap, least, 1e-12);
        EXPECT_GT(found[0].normal.minCoeff(), -1e-12);
        inside_octant += found[0].normal.minCoeff() > 1e-6 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(touching, 10);
  EXPECT_GT(inside_octant, 3);  // some contacts are the corner's own, not an edge's or a face's
}

}  // namespace
}  // namespace partimix::dem
