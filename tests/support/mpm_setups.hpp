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

// A fed bin in plane strain: the half (x in [0, 0.1], a symmetry plane at x = 0) of a bin
// 20 cm wide, filled 10 cm high with the seed's beads on a 5 mm lattice over a 1 cm grid, a slot
// 6 cm wide (x < 0.03 by symmetry) in its rough floor, a feed keeping y in [0.1, 0.12] full, and
// an exit plane 5 cm below the floor. Its domain: fed_bin_domain().
inline mpm::MpmConfig fed_bin() {
  mpm::MpmConfig config = mpm_config(0.01, seed_beads());
  config.fills = {box_fill(Vec3(0, 0, -1), Vec3(0.1, 0.1, 1), 0.005)};
  mpm::PointFeed feed;
  feed.region = std::make_shared<geometry::Box>(Vec3(0, 0.1, -1), Vec3(0.1, 0.12, 1));
  feed.spacing = 0.005;
  config.feeds = {feed};
  config.exits = {mpm::PointExit{Vec3(0, -0.05, 0), -Vec3::UnitY()}};
  mpm::GridWall floor;
  floor.surface = geometry::Box(Vec3(0.03, -0.05, -1), Vec3(0.2, 0.0, 1)).make_surface(true, {});
  config.walls = {floor, plane_wall(Vec3::Zero(), Vec3::UnitX(), mpm::GridBoundary::slip),
                  plane_wall(Vec3(0.1, 0, 0), -Vec3::UnitX(), mpm::GridBoundary::slip)};
  return config;
}

inline Domain fed_bin_domain() {
  return domain_2d(Vec3(-0.02, -0.1, 0), Vec3(0.12, 0.15, 0));
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
