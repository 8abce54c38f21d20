// The separating-axis test of dem/oriented_box.hpp against a brute-force search for a
// separating direction: boxes are disjoint exactly when some unit n has
// h_a(n) + h_b(-n) < n . (c_b - c_a), with the box's support function h(n) = sum_k e_k |n . u_k|.
// The search takes 20000 directions of a Fibonacci lattice; the test's 15 axes must agree with
// it wherever the best direction clears the boundary by a margin the lattice's spacing cannot
// close.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "dem/oriented_box.hpp"

namespace partimix::dem {
namespace {

double support(const OrientedBox& box, const Vec3& n) {
  return (box.rotation.transpose() * n).cwiseAbs().dot(box.half_extents);
}

// The largest n . d - h_a(n) - h_b(-n) over the lattice: > 0 means separated.
double best_separation(const OrientedBox& a, const OrientedBox& b) {
  const int count = 20000;
  double best = -1e300;
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / count;
    const double phi = k * std::numbers::pi * (3.0 - std::sqrt(5.0));
    const double r = std::sqrt(1.0 - z * z);
    const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
    best = std::max(best, n.dot(b.centre - a.centre) - support(a, n) - support(b, n));
  }
  return best;
}

TEST(OrientedBox, FacesEdgesAndContainment) {
  const OrientedBox unit{Vec3::Zero(), Mat3::Identity(), Vec3::Ones()};
  EXPECT_TRUE(boxes_overlap(unit, {Vec3(1.9, 0, 0), Mat3::Identity(), Vec3::Ones()}));
  EXPECT_FALSE(boxes_overlap(unit, {Vec3(2.1, 0, 0), Mat3::Identity(), Vec3::Ones()}));
  EXPECT_TRUE(boxes_overlap(unit, {Vec3(0.1, 0.2, 0), Mat3::Identity(), Vec3::Constant(0.1)}));
  // Turned by 45 degrees about z, its edge reaches sqrt(2) along x.
  const Mat3 turned = Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(boxes_overlap(unit, {Vec3(2.4, 0, 0), turned, Vec3::Ones()}));
  EXPECT_FALSE(boxes_overlap(unit, {Vec3(2.45, 0, 0), turned, Vec3::Ones()}));
  // Two edges crossed: only an edge-edge axis separates them.
  const Mat3 about_x = Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitX()).toRotationMatrix();
  const OrientedBox edge_a{Vec3::Zero(), turned, Vec3::Ones()};
  EXPECT_FALSE(boxes_overlap(edge_a, {Vec3(0, 2.86, 0), about_x, Vec3::Ones()}));
  EXPECT_TRUE(boxes_overlap(edge_a, {Vec3(0, 2.8, 0), about_x, Vec3::Ones()}));
}

TEST(OrientedBox, RandomPairsAgreeWithADirectionSearch) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> extent(0.2, 2.0);
  std::normal_distribution<double> gauss;
  const auto rotation = [&] {
    return Eigen::Quaterniond(gauss(random), gauss(random), gauss(random), gauss(random))
        .normalized()
        .toRotationMatrix();
  };
  int decided = 0;
  for (int k = 0; k < 300; ++k) {
    const OrientedBox a{Vec3::Zero(), rotation(),
                        Vec3(extent(random), extent(random), extent(random))};
    const Vec3 offset = 3.0 * Vec3(gauss(random), gauss(random), gauss(random)).normalized();
    const OrientedBox b{offset * std::uniform_real_distribution<double>(0.3, 1.3)(random),
                        rotation(), Vec3(extent(random), extent(random), extent(random))};
    const double separation = best_separation(a, b);
    if (std::abs(separation) < 0.05)
      continue;
    ++decided;
    EXPECT_EQ(boxes_overlap(a, b), separation < 0.0) << k << " " << separation;
  }
  EXPECT_GT(decided, 200);
}

}  // namespace
}  // namespace partimix::dem
