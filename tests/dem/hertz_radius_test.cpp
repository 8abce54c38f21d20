// The Hertz radius of superquadrics (dem/surface_curvature.hpp; docs/dem.md, "Hertz radius"):
// - the curvatures of the implicit surface against a sphere's 1/r and 1/r^2 and an ellipsoid's
//   closed forms (its tip: c (1/a^2 + 1/b^2) / 2 and c^2 / (a^2 b^2); anywhere:
//   K = 1 / (a b c h^2)^2 with h^2 = x^2/a^4 + y^2/b^4 + z^2/c^4), to 1e-10 relative;
// - on blocky grains, against the principal curvatures from the shape operator's eigenvalues
//   (P H P / |g| on the tangent plane, P = I - n n^T), an independent route, to 1e-9 relative;
// - the clamp on a flat face;
// - in the solver: a prolate spheroid (1.5 x 1.5 x 3 mm) dropped tip first at 1 m/s onto a
//   plane, e = 1, no friction: its largest overlap is the Hertz one,
//   (15 m v^2 / (16 E* sqrt(R)))^(2/5), with R = a^2 / c at the tip for the curvature options
//   and R = r (the equal-volume radius) by default, within 1% (the step resolves the contact
//   in about 100 steps).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "dem/dem_setups.hpp"
#include "dem/dem_solver.hpp"
#include "dem/surface_curvature.hpp"

namespace partimix::dem {
namespace {

using test::add_plane;
using test::box;

// A point of the surface in the direction u from the centre (the gauge is homogeneous).
Vec3 surface_point(const Superquadric& shape, const Vec3& u) {
  return u / std::pow(shape.value(u) + 1.0, 1.0 / shape.n1());
}

Vec3 random_direction(std::mt19937& random) {
  std::normal_distribution<> gauss;
  return Vec3(gauss(random), gauss(random), gauss(random)).normalized();
}

TEST(SurfaceCurvature, SphereAndEllipsoidClosedForms) {
  const Superquadric sphere(Vec3::Constant(0.7), 2.0, 2.0);
  const double a = 0.8, b = 1.3, c = 2.1;
  const Superquadric ellipsoid(Vec3(a, b, c), 2.0, 2.0);
  std::mt19937 random(3);
  for (int k = 0; k < 100; ++k) {
    const Vec3 p = surface_point(sphere, random_direction(random));
    EXPECT_NEAR(mean_curvature(sphere.gradient(p), sphere.hessian(p)), 1.0 / 0.7, 1e-12);
    EXPECT_NEAR(gaussian_curvature(sphere.gradient(p), sphere.hessian(p)), 1.0 / 0.49, 1e-12);
    const Vec3 q = surface_point(ellipsoid, random_direction(random));
    const double h2 =
        std::pow(q.x() / (a * a), 2) + std::pow(q.y() / (b * b), 2) + std::pow(q.z() / (c * c), 2);
    const double expected = 1.0 / std::pow(a * b * c * h2, 2);
    EXPECT_NEAR(gaussian_curvature(ellipsoid.gradient(q), ellipsoid.hessian(q)) / expected, 1.0,
                1e-10);
  }
  const Vec3 tip(0.0, 0.0, c);
  EXPECT_NEAR(mean_curvature(ellipsoid.gradient(tip), ellipsoid.hessian(tip)),
              0.5 * c * (1.0 / (a * a) + 1.0 / (b * b)), 1e-12);
  EXPECT_NEAR(gaussian_curvature(ellipsoid.gradient(tip), ellipsoid.hessian(tip)),
              c * c / (a * a * b * b), 1e-12);
}

// The principal curvatures as the eigenvalues of the shape operator on the tangent plane.
Eigen::Vector2d principal_curvatures(const Vec3& g, const Mat3& h) {
  const Vec3 n = g.normalized();
  const Vec3 e1 = n.unitOrthogonal();
  const Vec3 e2 = n.cross(e1);
  Eigen::Matrix2d shape_operator;
  shape_operator << e1.dot(h * e1), e1.dot(h * e2), e2.dot(h * e1), e2.dot(h * e2);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(shape_operator / g.norm()).eigenvalues();
}

TEST(SurfaceCurvature, BlockyGrainsMatchTheShapeOperator) {
  const Superquadric blocky(Vec3(1.0, 0.6, 1.4), 4.0, 6.0);
  std::mt19937 random(11);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p = surface_point(blocky, random_direction(random));
    const Vec3 g = blocky.gradient(p);
    const Mat3 h = blocky.hessian(p);
    const Eigen::Vector2d kappa = principal_curvatures(g, h);
    const double mean = 0.5 * kappa.sum();
    const double gauss = kappa.prod();
    EXPECT_NEAR(mean_curvature(g, h), mean, 1e-9 * std::abs(mean)) << p.transpose();
    EXPECT_NEAR(gaussian_curvature(g, h), gauss, 1e-9 * std::abs(gauss) + 1e-14) << p.transpose();
  }
}

TEST(SurfaceCurvature, RadiusIsClampedAboutTheEquivalentRadius) {
  const Superquadric blocky(Vec3(1.0, 1.0, 1.0), 10.0, 10.0);
  const double r = blocky.equivalent_radius();
  const Vec3 face(1.0, 0.0, 0.0);  // flat: both curvatures vanish
  EXPECT_DOUBLE_EQ(hertz_radius(blocky, face, HertzRadius::gaussian_curvature, 5.0), 5.0 * r);
  EXPECT_DOUBLE_EQ(hertz_radius(blocky, face, HertzRadius::mean_curvature, 5.0), 5.0 * r);
  EXPECT_DOUBLE_EQ(hertz_radius(blocky, face, HertzRadius::equivalent, 5.0), r);
  const Superquadric needle(Vec3(0.01, 0.01, 1.0), 2.0, 2.0);
  const Vec3 tip(0.0, 0.0, 1.0);  // radius 1e-4, far below r / 10
  EXPECT_DOUBLE_EQ(hertz_radius(needle, tip, HertzRadius::mean_curvature, 10.0),
                   needle.equivalent_radius() / 10.0);
}

constexpr double kDensity = 2500.0;
constexpr double kYoungsModulus = 1.0e8;
constexpr double kPoisson = 0.3;

// The spheroid dropped tip first: its largest overlap (c - lowest centre height).
double largest_overlap(HertzRadius kind, const Superquadric& shape) {
  Config config;
  config.species = {Species{"grain", kDensity, {kYoungsModulus, kPoisson}, shape}};
  config.particle_interactions = {Interaction{1.0, 0.0, 0.0}};
  config.wall_interactions = {Interaction{1.0, 0.0, 0.0}};
  config.hertz_radius = kind;
  add_plane(config, Vec3::Zero(), Vec3::UnitY());
  Grains grains;
  const double c = shape.half_axes().z();
  grains.position = {Vec3(0.0, c + 1.0e-6, 0.0)};
  grains.radius = {0.0};
  grains.species = {0};
  grains.velocity = {Vec3(0.0, -1.0, 0.0)};
  grains.orientation = {Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()))};
  ParticleStore store;
  DemSolver solver(store, box(0.05), config, Vec3::Zero(), grains);
  const double dt = 0.02 * solver.derived_parameters()["rayleigh_time [s]"];
  double lowest = store.position()[0].y();
  for (int n = 0; n < 200000 && store.velocity()[0].y() <= 0.0; ++n) {
    solver.step(dt);
    lowest = std::min(lowest, store.position()[0].y());
  }
  EXPECT_GT(store.velocity()[0].y(), 0.0);
  return c - lowest;
}

double hertz_overlap(double mass, double radius, double wall_modulus, double wall_poisson) {
  const double contact_modulus = 1.0 / ((1.0 - kPoisson * kPoisson) / kYoungsModulus +
                                        (1.0 - wall_poisson * wall_poisson) / wall_modulus);
  return std::pow(15.0 * mass / (16.0 * contact_modulus * std::sqrt(radius)), 0.4);
}

TEST(HertzRadius, SpheroidTipImpactHasTheHertzOverlapOfItsCurvature) {
  const double a = 1.5e-3, c = 3.0e-3;
  const Superquadric spheroid(Vec3(a, a, c), 2.0, 2.0);
  const double mass = kDensity * spheroid.volume();
  // The wall of dem_setups.hpp: steel, E = 2e11 Pa, nu = 0.3.
  const double tip = hertz_overlap(mass, a * a / c, 2.0e11, 0.3);
  const double equivalent = hertz_overlap(mass, spheroid.equivalent_radius(), 2.0e11, 0.3);
  EXPECT_NEAR(largest_overlap(HertzRadius::gaussian_curvature, spheroid) / tip, 1.0, 0.01);
  EXPECT_NEAR(largest_overlap(HertzRadius::mean_curvature, spheroid) / tip, 1.0, 0.01);
  EXPECT_NEAR(largest_overlap(HertzRadius::equivalent, spheroid) / equivalent, 1.0, 0.01);
}

}  // namespace
}  // namespace partimix::dem
