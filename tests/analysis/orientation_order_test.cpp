// Orientation order (docs/mixing.md, "Orientation order"), against exact values:
// - the axis of a grain: the long one, an oblate grain's short one, none for equal half-axes;
// - grains all along e (prolate along body x or z, oblate, triaxial; turned at random about
//   their axis, pointing either way): S_dir = S = 1 (to 1e-12);
// - grains all normal to e: S_dir = -1/2 (1e-12);
// - half along e, half along one direction p normal to it: S_dir = (1 - 1/2) / 2 = 1/4, and
//   Q = (3/4)(e e^T + p p^T) - I/2, eigenvalues 1/4, 1/4, -1/2: S = 1/4 (1e-12);
// - N = 10000 orientations uniform over all rotations: S_dir has mean 0 and standard deviation
//   sqrt(1/5) / sqrt(N) (Var P2 = 1/5), asserted within 4/sqrt(N); S is biased upwards at finite
//   N: over 2000 draws of N grains (N = 100 to 10000) its mean is 0.80/sqrt(N) and its largest
//   1.97/sqrt(N) (Monte Carlo); asserted 0 < S < 3/sqrt(N);
// - the velocity as reference: grains moving along or across their axis; grains not faster
//   than min_speed count in S but not in S_dir; in a rotating frame, grains turning with it are
//   at rest (S_dir of the flowing grains alone: -1/2, 1e-12);
// - spheres and walls count nowhere; no grain gives NaN; missing fields are a RunError.
#include "analysis/orientation_order.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "load_fixtures.hpp"
#include "support/uniform_random.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;
using test_support::Uniform;

constexpr double kPi = std::numbers::pi;
const Vec3 kProlateZ(1.0e-3, 1.0e-3, 3.0e-3);  // long axis z
const Vec3 kProlateX(2.0e-3, 1.0e-3, 1.0e-3);  // long axis x
const Vec3 kOblate(2.0e-3, 2.0e-3, 0.5e-3);    // symmetry axis z
const Vec3 kTriaxial(1.0e-3, 3.0e-3, 2.0e-3);  // long axis y
const Vec3 kSphere = Vec3::Constant(1.0e-3);

// A uniformly random rotation (Shoemake 1992, from three uniform numbers).
Eigen::Quaterniond random_rotation(Uniform& uniform) {
  const double u1 = uniform();
  const double u2 = 2.0 * kPi * uniform();
  const double u3 = 2.0 * kPi * uniform();
  return Eigen::Quaterniond(std::sqrt(1.0 - u1) * std::sin(u2), std::sqrt(1.0 - u1) * std::cos(u2),
                            std::sqrt(u1) * std::sin(u3), std::sqrt(u1) * std::cos(u3));
}

// A store of grains with the DEM fields of orientation and shape.
class Grains {
 public:
  Grains()
      : w_(store_.add_scalar("orientation_w", "", false)),
        v_(store_.add_vector("orientation_v", "", false)),
        axes_(store_.add_vector("half_axes", "m")) {}

  // A grain of `half_axes` turned by q, moving at `velocity`.
  void add(const Vec3& half_axes, const Eigen::Quaterniond& q, const Vec3& velocity = Vec3::Zero(),
           ParticleKind kind = ParticleKind::grain, const Vec3& position = Vec3::Zero()) {
    const std::size_t i = add_particle(store_, kind, position);
    w_.values[i] = q.w();
    v_.values[i] = q.vec();
    axes_.values[i] = half_axes;
    store_.velocity()[i] = velocity;
  }

  // A grain of `half_axes` whose axis points along `direction` (either way, turned at random
  // about it).
  void add_along(const Vec3& half_axes, const Vec3& direction, Uniform& uniform,
                 const Vec3& velocity = Vec3::Zero(), const Vec3& position = Vec3::Zero()) {
    const Vec3 body_axis = Vec3::Unit(grain_axis(half_axes));
    const double sign = uniform() < 0.5 ? -1.0 : 1.0;
    const Eigen::Quaterniond onto = Eigen::Quaterniond::FromTwoVectors(body_axis, sign * direction);
    const Eigen::AngleAxisd twist(2.0 * kPi * uniform(), direction.normalized());
    add(half_axes, Eigen::Quaterniond(twist) * onto, velocity, ParticleKind::grain, position);
  }

  const ParticleStore& store() const { return store_; }

 private:
  ParticleStore store_;
  Field<double>& w_;
  Field<Vec3>& v_;
  Field<Vec3>& axes_;
};

OrientationReference along(const Vec3& direction) {
  return {false, direction, 0.0};
}

// A unit vector normal to e, at angle `angle` about it.
Vec3 normal_to(const Vec3& e, double angle) {
  const Vec3 n1 = e.unitOrthogonal();
  const Vec3 n2 = e.normalized().cross(n1);
  return std::cos(angle) * n1 + std::sin(angle) * n2;
}

const Vec3 kDirection = Vec3(1.0, 2.0, -2.0) / 3.0;

TEST(OrientationOrder, GrainAxisIsTheLongOneOrAnOblateGrainsSymmetryAxis) {
  EXPECT_EQ(grain_axis(kProlateZ), 2);
  EXPECT_EQ(grain_axis(kProlateX), 0);
  EXPECT_EQ(grain_axis(kTriaxial), 1);
  EXPECT_EQ(grain_axis(kOblate), 2);
  EXPECT_EQ(grain_axis(Vec3(2.0, 1.0, 2.0)), 1);
  EXPECT_EQ(grain_axis(kSphere), -1);
}

TEST(OrientationOrder, GrainsAllAlongTheDirectionGiveOne) {
  Uniform uniform(1);
  Grains grains;
  for (int k = 0; k < 40; ++k) {
    for (const Vec3& shape : {kProlateZ, kProlateX, kOblate, kTriaxial})
      grains.add_along(shape, kDirection, uniform);
  }
  OrientationOrder order(along(3.0 * kDirection));  // normalised on use
  const auto values = sample_once(order, grains.store(), 0.0);
  EXPECT_NEAR(values[0], 1.0, 1e-12);
  EXPECT_NEAR(values[1], 1.0, 1e-12);
}

TEST(OrientationOrder, GrainsAllNormalToTheDirectionGiveMinusOneHalf) {
  Uniform uniform(2);
  Grains grains;
  for (int k = 0; k < 100; ++k)
    grains.add_along(k % 2 ? kProlateZ : kOblate, normal_to(kDirection, 2.0 * kPi * uniform()),
                     uniform);
  OrientationOrder order(along(kDirection));
  EXPECT_NEAR(sample_once(order, grains.store(), 0.0)[0], -0.5, 1e-12);
}

TEST(OrientationOrder, HalfAlongHalfNormalGiveOneQuarter) {
  Uniform uniform(3);
  Grains grains;
  const Vec3 p = normal_to(kDirection, 0.7);
  for (int k = 0; k < 50; ++k) {
    grains.add_along(kProlateX, kDirection, uniform);
    grains.add_along(kProlateZ, p, uniform);
  }
  OrientationOrder order(along(kDirection));
  const auto values = sample_once(order, grains.store(), 0.0);
  EXPECT_NEAR(values[0], 0.25, 1e-12);
  EXPECT_NEAR(values[1], 0.25, 1e-12);
}

TEST(OrientationOrder, IsotropicGrainsGiveZeroWithinTheirFiniteNumber) {
  constexpr int kGrains = 10000;
  Uniform uniform(4);
  Grains grains;
  for (int k = 0; k < kGrains; ++k)
    grains.add(k % 2 ? kProlateZ : kTriaxial, random_rotation(uniform));
  OrientationOrder order(along(kDirection));
  const auto values = sample_once(order, grains.store(), 0.0);
  const double root_n = std::sqrt(static_cast<double>(kGrains));
  EXPECT_LT(std::abs(values[0]), 4.0 / root_n) << values[0];
  EXPECT_GT(values[1], 0.0);
  EXPECT_LT(values[1], 3.0 / root_n) << values[1];
}

TEST(OrientationOrder, VelocityAsTheReference) {
  // Along their motion: 1; across it: -1/2. Grains at rest, or not faster than min_speed, count
  // in S only: with 10 grains along x moving along x and 10 along y at rest, S_dir = 1 and
  // S = 1/4 (half along x, half along y, as above).
  Uniform uniform(5);
  Grains moving;
  for (int k = 0; k < 10; ++k) {
    const Vec3 axis = normal_to(kDirection, 0.3 * k);
    moving.add_along(kProlateZ, axis, uniform, 0.2 * axis);
    moving.add_along(kOblate, axis, uniform, -0.5 * kDirection);
  }
  OrientationOrder velocity(OrientationReference{});
  EXPECT_NEAR(sample_once(velocity, moving.store(), 0.0)[0], (1.0 - 0.5) / 2.0, 1e-12);

  Grains resting;
  for (int k = 0; k < 10; ++k) {
    resting.add_along(kProlateZ, Vec3::UnitX(), uniform, Vec3(0.3, 0.0, 0.0));
    resting.add_along(kProlateZ, Vec3::UnitY(), uniform, k % 2 ? Vec3::Zero() : Vec3(0, 0, 0.01));
  }
  OrientationOrder slow(OrientationReference{true, Vec3::UnitX(), 0.01});
  const auto values = sample_once(slow, resting.store(), 0.0);
  EXPECT_NEAR(values[0], 1.0, 1e-12);
  EXPECT_NEAR(values[1], 0.25, 1e-12);
}

TEST(OrientationOrder, ARotatingFrameLeavesOutTheBedThatTurnsWithIt) {
  // A drum turning at omega about z through p: 10 grains turn with it (velocity omega x (x - p),
  // axis along it), 10 flow through it (velocity omega x (x - p) + 0.2 m/s along x, axis along
  // y). In the frame the turning grains are at rest and the flowing ones move along x, across
  // their axes: S_dir = -1/2 from the flowing grains alone. In the lab frame the turning grains
  // count along their motion: S_dir is above 0.
  Uniform uniform(9);
  const Vec3 point(0.1, -0.2, 0.0);
  const Vec3 omega(0.0, 0.0, kPi);
  Grains drum;
  for (int k = 0; k < 10; ++k) {
    const Vec3 x = point + 0.05 * Vec3(std::cos(0.6 * k), std::sin(0.6 * k), 0.01 * k);
    const Vec3 turning = omega.cross(x - point);
    drum.add_along(kProlateZ, turning.normalized(), uniform, turning, x);
    drum.add_along(kProlateZ, Vec3::UnitY(), uniform, turning + Vec3(0.2, 0.0, 0.0), x);
  }
  OrientationReference frame{true, Vec3::UnitX(), 0.01};
  frame.rotating_frame = true;
  frame.frame_point = point;
  frame.frame_angular_velocity = omega;
  OrientationOrder relative(frame);
  EXPECT_NEAR(sample_once(relative, drum.store(), 0.0)[0], -0.5, 1e-12);
  OrientationOrder lab(OrientationReference{true, Vec3::UnitX(), 0.01});
  EXPECT_GT(sample_once(lab, drum.store(), 0.0)[0], 0.2);
}

TEST(OrientationOrder, SpheresAndWallsCountNowhere) {
  Uniform uniform(6);
  Grains grains;
  for (int k = 0; k < 10; ++k) {
    grains.add_along(kProlateZ, kDirection, uniform);
    grains.add(kSphere, random_rotation(uniform));
    grains.add(kProlateZ, random_rotation(uniform), Vec3::Zero(), ParticleKind::wall);
  }
  OrientationOrder order(along(kDirection));
  const auto values = sample_once(order, grains.store(), 0.0);
  EXPECT_NEAR(values[0], 1.0, 1e-12);
  EXPECT_NEAR(values[1], 1.0, 1e-12);
}

TEST(OrientationOrder, NoGrainWithAnAxisGivesNaNAndNoFigures) {
  Grains grains;
  grains.add(kSphere, Eigen::Quaterniond::Identity());
  OrientationOrder order(along(kDirection));
  const auto values = sample_once(order, grains.store(), 0.0);
  EXPECT_TRUE(std::isnan(values[0]));
  EXPECT_TRUE(std::isnan(values[1]));
  Figures figures;
  order.add_figures(figures);
  EXPECT_TRUE(figures.empty());
}

TEST(OrientationOrder, MissingFieldsAreARunError) {
  ParticleStore store;
  add_particle(store, ParticleKind::grain, Vec3::Zero());
  OrientationOrder order(along(kDirection));
  try {
    sample_once(order, store, 0.0);
    FAIL() << "no RunError";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what()).find("orientation_w, orientation_v and half_axes"),
              std::string::npos);
  }
}

TEST(OrientationOrder, BadReferencesAreRefused) {
  EXPECT_THROW(OrientationOrder(along(Vec3::Zero())), std::invalid_argument);
  EXPECT_THROW(OrientationOrder(OrientationReference{true, Vec3::UnitX(), -1.0}),
               std::invalid_argument);
  OrientationReference fixed_in_a_frame = along(kDirection);
  fixed_in_a_frame.rotating_frame = true;
  EXPECT_THROW(OrientationOrder{fixed_in_a_frame}, std::invalid_argument);
}

TEST(OrientationOrder, RegisteredByNameWithFiguresAndReplay) {
  AnalysisOptions options;
  options.orientation = along(kDirection);
  const auto analysis = analysis_registry().create("orientation_order", options);
  ASSERT_NE(analysis, nullptr);
  ASSERT_EQ(analysis->columns().size(), 2u);
  EXPECT_EQ(analysis->columns()[0].name, "alignment");
  EXPECT_EQ(analysis->columns()[1].name, "nematic_order");
  const std::vector<double> row{0.375, 0.5};
  analysis->replay(1.0, row);
  Figures figures;
  analysis->add_figures(figures);
  EXPECT_EQ(figures.at("alignment_final"), 0.375);
  EXPECT_EQ(figures.at("nematic_order_final"), 0.5);
}

}  // namespace
}  // namespace partimix::analysis
