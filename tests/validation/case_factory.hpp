#pragma once
// Cases built in code for the validation tests (no case file needed).
#include <memory>

#include "geometry/shape.hpp"
#include "io/case.hpp"
#include "sph/sph_section.hpp"

namespace partimix::testing_cases {

// The SPH sections of a case built in code: a new one added to `c`, or the one it has.
inline sph::SphSection& add_sph(io::Case& c) {
  auto section = std::make_shared<sph::SphSection>();
  c.methods.push_back({"sph", section, 1});
  return *section;
}

inline sph::SphSection& sph_of(io::Case& c) {
  return c.section<sph::SphSection>("sph");
}

// A container wall: the box [lo, hi] with `open` faces.
inline io::WallSpec box_wall(const Vec3& lo, const Vec3& hi, std::vector<geometry::Face> open) {
  io::WallSpec wall;
  wall.shape = std::make_shared<geometry::Box>(lo, hi);
  wall.surface = wall.shape->make_surface(false, open);
  wall.open_faces = std::move(open);
  return wall;
}

// A 2D tank [0, width] x [0, 2 depth] with walls on the floor and sides, filled with water to
// `depth`, gravity -9.81 in y.
inline io::Case tank_2d(double width, double depth, double spacing) {
  io::Case c;
  c.name = "tank_2d";
  sph::SphSection& sph = add_sph(c);
  c.domain.dimensions = 2;
  const double margin = 4.0 * spacing;
  c.domain.lo = Vec3(-margin, -margin, 0.0);
  c.domain.hi = Vec3(width + margin, 2.0 * depth, 0.0);
  c.gravity = Vec3(0.0, -9.81, 0.0);
  sph.config.spacing = spacing;
  sph.fluid.density = 1000.0;
  sph.fluid.rheology.viscosity = 1.0e-3;
  sph.fluid.regions.push_back(
      {std::make_shared<geometry::Box>(Vec3(0.0, 0.0, -1.0), Vec3(width, depth, 1.0))});
  c.walls.push_back(
      box_wall(Vec3(0.0, 0.0, -1.0), Vec3(width, 2.0 * depth, 1.0), {geometry::Face{1, 1}}));
  return c;
}

}  // namespace partimix::testing_cases

namespace partimix::testing_cases {

// Poiseuille flow between plates y = 0 and y = width, periodic in x, driven by the body force
// `force` along x (Morris, Fox and Zhu 1997, section 4.1). `length` is the periodic length.
inline io::Case poiseuille_2d(double width, double length, double spacing, double force,
                              double density, double viscosity, double max_velocity) {
  io::Case c;
  c.name = "poiseuille_2d";
  sph::SphSection& sph = add_sph(c);
  c.domain.dimensions = 2;
  c.domain.lo = Vec3(0.0, -4.0 * spacing, 0.0);
  c.domain.hi = Vec3(length, width + 4.0 * spacing, 0.0);
  c.domain.periodic = {true, false, false};
  c.gravity = Vec3(force, 0.0, 0.0);
  sph.config.spacing = spacing;
  sph.config.max_velocity = max_velocity;
  sph.fluid.density = density;
  sph.fluid.rheology.viscosity = viscosity;
  const auto channel =
      std::make_shared<geometry::Box>(Vec3(0.0, 0.0, -1.0), Vec3(length, width, 1.0));
  sph.fluid.regions.push_back({channel});
  c.walls.push_back(box_wall(Vec3(0.0, 0.0, -1.0), Vec3(length, width, 1.0), {}));
  return c;
}

}  // namespace partimix::testing_cases

namespace partimix::testing_cases {

// Dam break of Koshizuka and Oka (1996): a water column `column` wide and 2 `column` high at the
// left end of a tank 4 `column` long, walls on floor and sides, open top.
inline io::Case dam_break_2d(double column, double spacing) {
  io::Case c;
  c.name = "dam_break_2d";
  sph::SphSection& sph = add_sph(c);
  c.domain.dimensions = 2;
  const double margin = 4.0 * spacing;
  c.domain.lo = Vec3(-margin, -margin, 0.0);
  c.domain.hi = Vec3(4.0 * column + margin, 3.0 * column, 0.0);
  c.gravity = Vec3(0.0, -9.81, 0.0);
  sph.config.spacing = spacing;
  sph.fluid.density = 1000.0;
  sph.fluid.rheology.viscosity = 1.0e-3;
  sph.fluid.regions.push_back(
      {std::make_shared<geometry::Box>(Vec3(0.0, 0.0, -1.0), Vec3(column, 2.0 * column, 1.0))});
  c.walls.push_back(box_wall(Vec3(0.0, 0.0, -1.0), Vec3(4.0 * column, 3.0 * column, 1.0),
                             {geometry::Face{1, 1}}));
  return c;
}

}  // namespace partimix::testing_cases
