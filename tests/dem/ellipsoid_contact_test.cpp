// Contact detection between ellipsoids by the Perram-Wertheim contact function
// (dem/ellipsoid_contact.hpp; docs/dem.md, "Ellipsoid pairs: the midway point in one unknown").
// Random ellipsoid pairs against the brute-force reference of superquadric_reference.hpp and
// against the general midway point's Newton iteration (find_midway_contact), which must give the
// same contact; spheres in closed form; the warm start and the one-evaluation rejection of near
// misses that make it cheap.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "dem/ellipsoid_contact.hpp"
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

Ellipsoid ellipsoid_of(const GrainPose& g) {
  return make_ellipsoid(g.centre, g.rotation, g.shape->half_axes());
}

TEST(EllipsoidContact, TwoSpheresHaveTheClosedForm) {
  const Vec3 u = Vec3(0.3, -0.8, 0.5).normalized();
  const Mat3 turned = Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  const Ellipsoid i = make_ellipsoid(Vec3(0.3, -0.2, 0.5), turned, Vec3::Constant(1.0));
  for (const double d : {1.69, 1.5, 1.0}) {
    const Ellipsoid j = make_ellipsoid(i.centre + d * u, Mat3::Identity(), Vec3::Constant(0.7));
    const SuperquadricContact c = find_ellipsoid_contact(i, j, std::nullopt);
    ASSERT_TRUE(c.converged && c.touching);
    EXPECT_NEAR(c.overlap, 1.7 - d, 1e-12);
    EXPECT_LT(angle(c.normal, u), 1e-12);
    EXPECT_LT((c.point - (i.centre + 0.5 * (1.0 + d - 0.7) * u)).norm(), 1e-12);
    EXPECT_NEAR(c.mu * c.mu, 0.7, 1e-12);  // mu^2 = R_j / R_i
  }
  const Ellipsoid apart =
      make_ellipsoid(i.centre + 1.7000001 * u, Mat3::Identity(), Vec3::Constant(0.7));
  EXPECT_FALSE(find_ellipsoid_contact(i, apart, std::nullopt).near);
}

TEST(EllipsoidContact, CoincidentCentresAreAFailureNotAContact) {
  const Ellipsoid i = make_ellipsoid(Vec3::Zero(), Mat3::Identity(), Vec3(1.0, 2.0, 3.0));
  const SuperquadricContact c = find_ellipsoid_contact(i, i, std::nullopt);
  EXPECT_FALSE(c.converged);
  EXPECT_FALSE(c.touching);
}

// Gaps along the centre line in units of the smaller half-axis: overlaps up to 0.25 and down to
// 1e-7, gaps as small and up to 0.5.
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

// Every pair converges and touches exactly when the reference's common scale is below 1 (pairs
// within 1e-9 of it left out); for touching pairs sqrt(F*) is the reference's scale (1e-9), the
// normal its normal (1e-6 rad), and the overlap, contact point and normal those of the general
// Newton iteration (1e-9 L, 1e-9 rad), whose warm-start multiplier mu it shares (1e-9).
TEST(EllipsoidContact, RandomPairsMatchTheReferenceAndTheGeneralMidwayPoint) {
  reference::PairMaker maker(31, 1.0);
  const int pairs = 1000;
  int failures = 0, missed = 0, false_contacts = 0, touching = 0, iterations = 0, most = 0;
  int centre_line = 0;  // pairs proven apart by the separating axis, without an evaluation of F
  double worst_scale = 0.0, worst_normal = 0.0, worst_mu = 0.0;
  double worst_overlap = 0.0, worst_point = 0.0, worst_turn = 0.0;
  for (int k = 0; k < pairs; ++k) {
    const reference::RandomPair pair = maker.make(random_gap(k, maker));
    const SuperquadricContact c =
        find_ellipsoid_contact(ellipsoid_of(pair.i), ellipsoid_of(pair.j), std::nullopt);
    if (!c.converged) {
      ++failures;
      continue;
    }
    iterations += c.iterations;
    most = std::max(most, c.iterations);
    centre_line += c.iterations == 0;
    const double scale = pair.midway.scale;
    if (std::abs(scale - 1.0) < 1e-9)
      continue;
    missed += scale < 1.0 && !c.touching;
    false_contacts += scale > 1.0 && c.touching;
    if (!c.touching || scale > 1.0)
      continue;
    ++touching;
    const Vec3 from_i = pair.i.rotation.transpose() * (c.midway - pair.i.centre);
    worst_scale =
        std::max(worst_scale, std::abs(std::sqrt(pair.shape_i->value(from_i) + 1.0) - scale));
    worst_normal = std::max(worst_normal, angle(c.normal, pair.midway.normal));
    const SuperquadricContact general = find_midway_contact(pair.i, pair.j, std::nullopt);
    ASSERT_TRUE(general.converged && general.touching);
    worst_overlap = std::max(worst_overlap, std::abs(c.overlap - general.overlap) / pair.length);
    worst_point = std::max(worst_point, (c.point - general.point).norm() / pair.length);
    worst_turn = std::max(worst_turn, angle(c.normal, general.normal));
    worst_mu = std::max(worst_mu, std::abs(c.mu - general.mu));
  }
  RecordProperty("touching", touching);
  RecordProperty("rejected_on_the_centre_line", centre_line);
  RecordProperty("mean_iterations", figure(double(iterations) / pairs));
  RecordProperty("most_iterations", most);
  RecordProperty("worst_scale", figure(worst_scale));
  RecordProperty("worst_normal_rad", figure(worst_normal));
  RecordProperty("worst_overlap_against_general", figure(worst_overlap));
  RecordProperty("worst_point_against_general", figure(worst_point));
  RecordProperty("worst_normal_against_general", figure(worst_turn));
  RecordProperty("worst_mu_against_general", figure(worst_mu));
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(false_contacts, 0);
  EXPECT_GT(touching, pairs / 2);
  EXPECT_GT(centre_line, 0);
  EXPECT_LT(worst_scale, 1e-9);
  EXPECT_LT(worst_normal, 1e-6);
  EXPECT_LT(worst_overlap, 1e-9);
  EXPECT_LT(worst_point, 1e-9);
  EXPECT_LT(worst_turn, 1e-9);
  EXPECT_LT(worst_mu, 1e-9);
}

// A touching random pair whose grain j then moved by `shift` L in a random direction and turned
// by `turn` rad about a random axis (a pair's motion between two detections), with its contact
// after the motion warm-started from the one before, and started cold.
struct MovedPair {
  reference::RandomPair pair;
  SuperquadricContact warm;
  SuperquadricContact cold;
};

MovedPair moved_touching_pair(reference::PairMaker& maker, double shift, double turn) {
  MovedPair moved{maker.make(-maker.uniform(0.01, 0.2)), {}, {}};
  reference::RandomPair& pair = moved.pair;
  const SuperquadricContact before =
      find_ellipsoid_contact(ellipsoid_of(pair.i), ellipsoid_of(pair.j), std::nullopt);
  EXPECT_TRUE(before.touching);
  const Vec3 direction = Vec3(maker.uniform(-1, 1), maker.uniform(-1, 1), maker.uniform(-1, 1));
  pair.j.centre += shift * pair.length * direction.normalized();
  const Vec3 axis = Vec3(1.0, maker.uniform(-1, 1), 0.5).normalized();
  pair.j.rotation = Eigen::AngleAxisd(turn, axis).toRotationMatrix() * pair.j.rotation;
  moved.warm = find_ellipsoid_contact(ellipsoid_of(pair.i), ellipsoid_of(pair.j), before.mu);
  moved.cold = find_ellipsoid_contact(ellipsoid_of(pair.i), ellipsoid_of(pair.j), std::nullopt);
  return moved;
}

// After a small motion (j moves by 1% of L and turns by 1 degree) the iteration restarted from
// the last multiplier takes at most 4 evaluations of F (2.0 on average) to the cold start's
// contact; a pair then moved apart along its normal by its overlap and 5% of L is rejected by
// the centre-line test or the first evaluation in most cases (F(t) > 1 at the last step's t
// proves it apart).
TEST(EllipsoidContact, WarmStartsAndNearMissesAreCheap) {
  reference::PairMaker maker(8, 1.0);
  int warm_steps = 0, most = 0, rejected_at_once = 0;
  const int pairs = 200;
  for (int k = 0; k < pairs; ++k) {
    auto [pair, warm, cold] = moved_touching_pair(maker, 0.01, std::numbers::pi / 180.0);
    ASSERT_TRUE(warm.converged && warm.touching);
    EXPECT_NEAR(warm.overlap, cold.overlap, 1e-12 * pair.length);
    EXPECT_LT(angle(warm.normal, cold.normal), 1e-10);
    warm_steps += warm.iterations;
    most = std::max(most, warm.iterations);
    pair.j.centre += (warm.overlap + 0.05 * pair.length) * warm.normal;
    const SuperquadricContact apart =
        find_ellipsoid_contact(ellipsoid_of(pair.i), ellipsoid_of(pair.j), warm.mu);
    ASSERT_TRUE(apart.converged);
    EXPECT_FALSE(apart.touching);
    rejected_at_once += apart.iterations <= 1;  // 0: by the centre-line test
  }
  RecordProperty("mean_warm_iterations", figure(double(warm_steps) / pairs));
  RecordProperty("rejected_at_once", rejected_at_once);
  EXPECT_LE(most, 4);
  EXPECT_GT(rejected_at_once, pairs * 3 / 4);
}

// A DEM step moves a touching pair by about 1e-4 of its length (the seed drum: 3 um a step on
// 8 mm grains): restarted from the last multiplier, Newton's first step is then small enough
// to be the last, taken to second order (docs/dem.md). One evaluation of F in at least 3/4 of
// the pairs (measured: 85%), with the contact of the cold start to round-off: overlap 1e-13 L,
// normal 1e-13 rad, contact point 1e-12 L, mu 1e-12 (measured: 7e-15, 1.5e-14, 1.3e-13,
// 7.8e-14; the first-order last step of |s| <= 1e-7 it replaces gave 6e-14, 6e-15, 1.5e-13,
// 8e-14 with two evaluations).
TEST(EllipsoidContact, ADemStepsMotionTakesOneEvaluationToRoundOff) {
  reference::PairMaker maker(17, 1.0);
  int once = 0;
  double worst_overlap = 0.0, worst_normal = 0.0, worst_point = 0.0, worst_mu = 0.0;
  const int pairs = 400;
  for (int k = 0; k < pairs; ++k) {
    const auto [pair, warm, cold] = moved_touching_pair(maker, 1e-4, 1e-4);
    ASSERT_TRUE(warm.converged && warm.touching && cold.touching);
    once += warm.iterations == 1;
    worst_overlap = std::max(worst_overlap, std::abs(warm.overlap - cold.overlap) / pair.length);
    worst_normal = std::max(worst_normal, angle(warm.normal, cold.normal));
    worst_point = std::max(worst_point, (warm.point - cold.point).norm() / pair.length);
    worst_mu = std::max(worst_mu, std::abs(warm.mu - cold.mu));
  }
  RecordProperty("one_evaluation", once);
  RecordProperty("worst_overlap", figure(worst_overlap));
  RecordProperty("worst_normal_rad", figure(worst_normal));
  RecordProperty("worst_point", figure(worst_point));
  RecordProperty("worst_mu", figure(worst_mu));
  EXPECT_GE(once, pairs * 3 / 4);
  EXPECT_LT(worst_overlap, 1e-13);
  EXPECT_LT(worst_normal, 1e-13);
  EXPECT_LT(worst_point, 1e-12);
  EXPECT_LT(worst_mu, 1e-12);
}

}  // namespace
}  // namespace partimix::dem
