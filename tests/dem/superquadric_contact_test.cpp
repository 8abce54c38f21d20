// Contact detection between superquadric grains (dem/superquadric_contact.hpp; docs/dem.md,
// "Superquadric grains"). Closed forms: spheres, and ellipsoids and blocky grains on a common
// principal axis. Random pairs (superquadric_random_pairs.hpp) against the brute-force
// reference of superquadric_reference.hpp, which searches all directions with the grains'
// support functions: the midway point itself (its common scale from the values of
// Superquadric::value at X, the normal, the overlap by bisection along the normal line) to
// round-off, the touching decision on every pair, and the overlap, normal and contact point
// against the penetration depth (the shortest separating translation) within the midway
// point's model error, which is second order in the overlap. Then the warm start.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "dem/superquadric.hpp"
#include "dem/superquadric_contact.hpp"
#include "superquadric_random_pairs.hpp"
#include "superquadric_reference.hpp"

namespace partimix::dem {
namespace {

std::string figure(double value) {
  return fmt::format("{:.3g}", value);
}

double angle(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

Mat3 turn(double radians, const Vec3& axis) {
  return Eigen::AngleAxisd(radians, axis.normalized()).toRotationMatrix();
}

// Two grains on a common principal axis: grain i's x axis and grain j's x axis (or -x) along the
// world direction u, j turned about it by any angle. The midway point is on the axis, where both
// gradients point along it, so the overlap is a_i + a_j - d.
void expect_axial_overlap(const Superquadric& si, const Superquadric& sj, double d) {
  const Mat3 q = turn(0.7, Vec3(1.0, 2.0, -0.5));
  const Vec3 u = q.col(0);
  const GrainPose i{&si, Vec3(0.3, -1.2, 2.0), q};
  const GrainPose j{&sj, i.centre + d * u, q * turn(1.1, Vec3::UnitX())};
  const SuperquadricContact c = find_contact(i, j, std::nullopt);
  const double ai = si.half_axes().x();
  const double aj = sj.half_axes().x();
  ASSERT_TRUE(c.converged);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.overlap, ai + aj - d, 1e-10);
  EXPECT_LT(angle(c.normal, u), 1e-8);
  const Vec3 point = 0.5 * (i.centre + ai * u + j.centre - aj * u);
  EXPECT_LT((c.point - point).norm(), 1e-8);
}

TEST(SuperquadricContact, TwoSpheresHaveTheClosedForm) {
  const Superquadric si(Vec3::Constant(1.0), 2.0, 2.0);
  const Superquadric sj(Vec3::Constant(0.7), 2.0, 2.0);
  const Vec3 u = Vec3(0.3, -0.8, 0.5).normalized();
  for (const double d : {1.69, 1.5, 1.4}) {
    const GrainPose i{&si, Vec3(0.3, -0.2, 0.5), turn(0.4, Vec3(1, 1, 0))};
    const GrainPose j{&sj, i.centre + d * u, turn(2.0, Vec3(0, 1, 3))};
    const SuperquadricContact c = find_contact(i, j, std::nullopt);
    ASSERT_TRUE(c.converged && c.touching);
    EXPECT_NEAR(c.overlap, 1.7 - d, 1e-10);
    EXPECT_LT(angle(c.normal, u), 1e-10);
    EXPECT_LT((c.point - (i.centre + 0.5 * (1.0 + d - 0.7) * u)).norm(), 1e-10);
  }
}

TEST(SuperquadricContact, SphereAndEllipsoidOnAPrincipalAxis) {
  expect_axial_overlap(Superquadric(Vec3::Constant(0.8), 2.0, 2.0),
                       Superquadric(Vec3(1.5, 0.7, 1.1), 2.0, 2.0), 2.1);
}

TEST(SuperquadricContact, EllipsoidsOnACommonAxisOverlapByTheirHalfAxes) {
  const Superquadric si(Vec3(1.2, 0.6, 0.9), 2.0, 2.0);
  const Superquadric sj(Vec3(0.8, 1.4, 0.5), 2.0, 2.0);
  for (const double d : {1.99, 1.9, 1.7})
    expect_axial_overlap(si, sj, d);
}

TEST(SuperquadricContact, BlockyGrainsFaceToFace) {
  const Superquadric si(Vec3(1.0, 0.8, 0.6), 10.0, 10.0);
  const Superquadric sj(Vec3(0.5, 0.9, 1.1), 8.0, 6.0);
  for (const double d : {1.499, 1.45, 1.3})
    expect_axial_overlap(si, sj, d);
  expect_axial_overlap(si, Superquadric(Vec3(0.7, 0.7, 0.7), 2.0, 2.0), 1.6);
}

TEST(SuperquadricContact, SeparatedAndBarelyTouchingSpheres) {
  const Superquadric sphere(Vec3::Constant(1.0), 2.0, 2.0);
  const GrainPose i{&sphere, Vec3::Zero(), Mat3::Identity()};
  for (const double gap : {1e-9, 1e-3, 0.5, 3.0}) {
    const GrainPose j{&sphere, Vec3(2.0 + gap, 0.0, 0.0), Mat3::Identity()};
    const SuperquadricContact c = find_contact(i, j, std::nullopt);
    EXPECT_TRUE(c.converged);
    EXPECT_FALSE(c.touching) << gap;
  }
  const GrainPose j{&sphere, Vec3(2.0 - 1e-9, 0.0, 0.0), Mat3::Identity()};
  const SuperquadricContact c = find_contact(i, j, std::nullopt);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.overlap, 1e-9, 1e-13);
}

// Gaps along the centre line, in units of the smaller half-axis: 60% overlaps up to 0.25, 10%
// overlaps down to 1e-7, 10% gaps as small and 20% gaps up to 0.5.
double random_gap(int k, reference::PairMaker& maker) {
  switch (k % 10) {
    case 6:
      return -maker.log_uniform(1e-7, 1e-3);
    case 7:
      return maker.log_uniform(1e-7, 1e-3);
    case 8:
    case 9:
      return maker.uniform(1e-3, 0.5);
    default:
      return -maker.uniform(1e-3, 0.25);
  }
}

// N = (F + 1)^(1/n1) from Superquadric::value: the gauge, computed apart from the contact code.
double gauge_norm(const GrainPose& g, const Vec3& x) {
  return std::pow(g.shape->value(g.rotation.transpose() * (x - g.centre)) + 1.0,
                  1.0 / g.shape->n1());
}

// Every pair: converged, touching exactly when the reference's common scale is below 1 (pairs
// within 1e-9 of it left out). Touching pairs: both gauges at X equal the reference's scale
// (1e-9, which makes X a minimiser of max(N_i, N_j)), the normal is the reference's (1e-6 rad),
// and the overlap and contact point agree with a bisection on F along the normal line
// (1e-9 L).
TEST(SuperquadricContact, RandomPairsMatchTheBruteForceMidwayPoint) {
  reference::PairMaker maker(2024);
  const int pairs = 1000;
  int failures = 0, missed = 0, false_contacts = 0, touching = 0, iterations = 0;
  int most_iterations = 0;
  double worst_scale = 0.0, worst_normal = 0.0, worst_overlap = 0.0;
  double seconds = 0.0;
  for (int k = 0; k < pairs; ++k) {
    const reference::RandomPair pair = maker.make(random_gap(k, maker));
    const auto start = std::chrono::steady_clock::now();
    const SuperquadricContact c = find_contact(pair.i, pair.j, std::nullopt);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!c.converged) {
      ++failures;
      continue;
    }
    iterations += c.iterations;
    most_iterations = std::max(most_iterations, c.iterations);
    const double scale = pair.midway.scale;
    if (std::abs(scale - 1.0) < 1e-9)
      continue;
    missed += scale < 1.0 && !c.touching;
    false_contacts += scale > 1.0 && c.touching;
    if (!c.touching || scale > 1.0)
      continue;
    ++touching;
    worst_scale = std::max({worst_scale, std::abs(gauge_norm(pair.i, c.midway) - scale),
                            std::abs(gauge_norm(pair.j, c.midway) - scale)});
    worst_normal = std::max(worst_normal, angle(c.normal, pair.midway.normal));
    const double si = reference::surface_distance(pair.i, c.midway, c.normal);
    const double sj = reference::surface_distance(pair.j, c.midway, -c.normal);
    const Vec3 point = c.midway + 0.5 * (si - sj) * c.normal;
    worst_overlap = std::max({worst_overlap, std::abs(c.overlap - (si + sj)) / pair.length,
                              (c.point - point).norm() / pair.length});
  }
  RecordProperty("pairs", pairs);
  RecordProperty("touching", touching);
  RecordProperty("not_converged", failures);
  RecordProperty("mean_iterations", figure(double(iterations) / (pairs - failures)));
  RecordProperty("most_iterations", most_iterations);
  RecordProperty("ns_per_call", figure(seconds / pairs * 1e9));
  RecordProperty("worst_scale", figure(worst_scale));
  RecordProperty("worst_normal_rad", figure(worst_normal));
  RecordProperty("worst_overlap_over_L", figure(worst_overlap));
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(false_contacts, 0);
  EXPECT_GT(touching, pairs / 2);
  EXPECT_LT(worst_scale, 1e-9);
  EXPECT_LT(worst_normal, 1e-6);
  EXPECT_LT(worst_overlap, 1e-9);
}

// The midway point's overlap, normal and contact point against the penetration depth d, its
// direction and the midpoint of the grains' deepest points. They agree to first order: measured
// on 2100 pairs, |overlap - d| <= 0.42 d^2 / L (0.50 on these), the angle <= 0.63 d / L and,
// for grains with n <= 6, the points within 0.81 d (the deepest points of blockier grains move by
// most of a face when the direction turns a little: there only the point's being inside both grains
// is checked).
TEST(SuperquadricContact, RandomOverlapsMatchThePenetrationDepth) {
  reference::PairMaker maker(77);
  const int pairs = 400;
  double worst_overlap = 0.0, worst_normal = 0.0, worst_point = 0.0, mean_relative = 0.0;
  for (int k = 0; k < pairs; ++k) {
    const reference::RandomPair pair =
        maker.make(k % 5 == 0 ? -maker.log_uniform(1e-6, 1e-2) : -maker.uniform(1e-2, 0.25));
    const SuperquadricContact c = find_contact(pair.i, pair.j, std::nullopt);
    ASSERT_TRUE(c.converged && c.touching);
    const reference::Penetration p = reference::penetration(pair.i, pair.j);
    const double l = pair.length;
    const double depth = p.depth / l;
    ASSERT_GT(depth, 0.0);
    worst_overlap =
        std::max(worst_overlap, std::abs(c.overlap - p.depth) / l / (depth * depth + 1e-6));
    mean_relative += std::abs(c.overlap / p.depth - 1.0) / pairs;
    worst_normal = std::max(worst_normal, angle(c.normal, p.normal) / (depth + 1e-3));
    EXPECT_LE(gauge_norm(pair.i, c.point), 1.0 + 1e-12);
    EXPECT_LE(gauge_norm(pair.j, c.point), 1.0 + 1e-12);
    const double blockiest =
        std::max({pair.shape_i->n1(), pair.shape_i->n2(), pair.shape_j->n1(), pair.shape_j->n2()});
    if (blockiest <= 6.0)
      worst_point = std::max(worst_point, (c.point - p.point).norm() / l / (depth + 1e-3));
  }
  RecordProperty("worst_overlap_error_over_d2", figure(worst_overlap));
  RecordProperty("mean_relative_overlap_error", figure(mean_relative));
  RecordProperty("worst_normal_angle_over_d", figure(worst_normal));
  RecordProperty("worst_point_error_over_d", figure(worst_point));
  EXPECT_LT(worst_overlap, 0.75);
  EXPECT_LT(worst_normal, 1.0);
  EXPECT_LT(worst_point, 1.2);
}

// After a small motion (j moves by 1% of L and turns by 1 degree), the midway point's Newton
// iteration restarted from the last midway point and multiplier converges in at most 4 steps (3 on
// average; the cold start takes 5) to the cold start's answer.
TEST(SuperquadricContact, WarmStartConvergesInFewSteps) {
  reference::PairMaker maker(5);
  int warm_steps = 0, cold_steps = 0, most = 0;
  const int pairs = 200;
  for (int k = 0; k < pairs; ++k) {
    reference::RandomPair pair = maker.make(-maker.uniform(0.01, 0.2));
    const SuperquadricContact before = find_midway_contact(pair.i, pair.j, std::nullopt);
    ASSERT_TRUE(before.touching);
    pair.j.centre +=
        0.01 * pair.length *
        Vec3(maker.uniform(-1, 1), maker.uniform(-1, 1), maker.uniform(-1, 1)).normalized();
    pair.j.rotation =
        turn(std::numbers::pi / 180.0, Vec3(1.0, maker.uniform(-1, 1), 0.5)) * pair.j.rotation;
    const SuperquadricContact warm =
        find_midway_contact(pair.i, pair.j, MidwayStart{before.midway, before.mu});
    const SuperquadricContact cold = find_midway_contact(pair.i, pair.j, std::nullopt);
    ASSERT_TRUE(warm.converged && warm.touching);
    EXPECT_NEAR(warm.overlap, cold.overlap, 1e-9 * pair.length);
    EXPECT_LT(angle(warm.normal, cold.normal), 1e-7);
    warm_steps += warm.iterations;
    cold_steps += cold.iterations;
    most = std::max(most, warm.iterations);
  }
  RecordProperty("mean_warm_iterations", figure(double(warm_steps) / pairs));
  RecordProperty("mean_cold_iterations", figure(double(cold_steps) / pairs));
  EXPECT_LE(most, 4);
  EXPECT_LT(warm_steps, 3.2 * pairs);
}

}  // namespace
}  // namespace partimix::dem
