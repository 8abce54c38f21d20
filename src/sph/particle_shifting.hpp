#pragma once
// Fickian particle shifting (docs/sph.md, "Particle shifting"; Lind et al. 2012, with the
// diffusion coefficient of Sun et al.'s delta-plus SPH, 2017): after a step, each fluid particle
// moves down the gradient of the particle concentration by dr_i = -A h U dt grad C_i, U the
// largest fluid speed, tangentially only near a free surface, at most 0.1 dp.
#include <cstdint>
#include <vector>

#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

// What one fluid particle's neighbours say about its place in the particle arrangement.
struct Concentration {
  Vec3 gradient = Vec3::Zero();        // grad C_i with Monaghan's (2000) pair term
  Vec3 plain_gradient = Vec3::Zero();  // grad C_i without it: the surface normal's direction
  double position_divergence = 0.0;    // div r_i: d in the bulk, about d / 2 at a surface
};

// A fluid particle lies at a free surface when its position divergence is below 0.75 d (d in the
// bulk; Lind et al. 2012 use 1.5 in 2D): the shifting and the pressure equation's Dirichlet rows
// share it (docs/sph.md, "Particle shifting").
inline bool at_free_surface(double position_divergence, int dimensions) {
  return position_divergence < 0.75 * dimensions;
}

// The sums over fluid and wall neighbours j of fluid particle i (grid built at the current
// positions, wall densities set).
Concentration concentration_of(std::size_t i, const Fields& fields, const CellGrid& grid,
                               const KernelTable& kernel, const Parameters& parameters);

struct ShiftingStep {
  double coefficient = 4.0;  // A
  double speed = 0.0;        // U [m/s]: the largest fluid speed
};

// Arrays kept between steps (resized, never shrunk): no allocation in the step.
struct ShiftingScratch {
  std::vector<Vec3> shift;
  std::vector<Vec3> normal;           // outward unit normal of a free surface
  std::vector<std::uint8_t> surface;  // 1: at a free surface
};

// Moves the fluid particles [0, fluid_count) of `fields` by their shifts, computed from the
// positions before any of them moves. A particle at a free surface, or with one within its
// kernel support, keeps only the part of its shift tangent to the surface. The first pass writes
// every particle's shift, normal and surface flag, the second projects its shift.
void shift_particles(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                     const KernelTable& kernel, const Parameters& parameters,
                     const ShiftingStep& settings, double dt, ShiftingScratch& scratch);

}  // namespace partimix::sph
