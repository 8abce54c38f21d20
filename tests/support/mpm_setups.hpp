#pragma once
// Small MPM set-ups built without a case file, for the MPM unit and validation tests: the
// seed's ceramic beads (seed 003, section 3.1) with a reduced stiffness, a 2D domain, walls as
// planes, and a box of points.
#include <memory>

#include "geometry/plane.hpp"
#include "geometry/shape.hpp"
#include "mpm/config.hpp"
#include "mpm/mpm_solver.hpp"

namespace partimix::test_support {

inline materials::GranularMaterial seed_beads(double youngs_modulus = 1.0e7) {
  materials::GranularMaterial m;
  m.name = "beads";
  m.density = 2200.0;
  m.packing_fraction = 0.6;
  m.youngs_modulus = youngs_modulus;
  m.poisson_ratio = 0.3;
  m.grain_diameter = 0.005;
  m.mu_s = 0.404;
  m.mu_2 = 0.64;
  m.i0 = 0.28;
  return m;
}

inline Domain domain_2d(const Vec3& lo, const Vec3& hi, bool periodic_x = false) {
  Domain domain;
  domain.dimensions = 2;
  domain.lo = lo;
  domain.hi = hi;
  domain.periodic[0] = periodic_x;
  return domain;
}

// A plane wall through `point` with the material on the side of `normal`.
inline mpm::GridWall plane_wall(const Vec3& point, const Vec3& normal, mpm::GridBoundary boundary,
                                double friction = 0.0) {
  mpm::GridWall wall;
  wall.surface = geometry::Plane(point, normal).make_surface(false, {});
  wall.boundary = boundary;
  wall.friction = friction;
  return wall;
}

inline mpm::PointFill box_fill(const Vec3& lo, const Vec3& hi, double spacing) {
  mpm::PointFill fill;
  fill.region = std::make_shared<geometry::Box>(lo, hi);
  fill.spacing = spacing;
  return fill;
}

inline mpm::MpmConfig mpm_config(double cell_size, const materials::GranularMaterial& material) {
  mpm::MpmConfig config;
  config.cell_size = cell_size;
  config.materials = {material};
  return config;
}

// Steps the solver at its stable step to `end`; returns the steps taken.
inline int run_mpm(mpm::MpmSolver& solver, double end) {
  int steps = 0;
  while (solver.time() < end - 1e-12) {
    solver.step(std::min(solver.stable_dt(), end - solver.time()));
    ++steps;
  }
  return steps;
}

}  // namespace partimix::test_support
