#pragma once
// The force of the fluid on every wall particle (docs/power.md; the seed's eq. 23): the
// reaction to the pair terms that wall particle j exerts on its fluid neighbours,
// f_j = -sum_i m_i a_(i<-j), except for the parts that a uniform field would give (a uniform
// pressure; with the Morris operator, the rigid-wall traction eta n x omega): those the pair
// sums integrate over the fluid particles around j, which are not arranged as on a lattice, so
// they are taken from the body's own particles instead, which are (docs/power.md, "Uniform parts
// of the load"). A uniform pressure then exerts no force and no torque on a body, whatever the
// fluid's arrangement. Each pair force acts at the midpoint of the pair, where the wall surface
// lies between the first fluid and wall layers; a wall particle's couple
// c_j = sum_i (x_i - x_j) / 2 x f_ij makes its moment about any point o (x_j - o) x f_j + c_j.
#include <vector>

#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

struct WallLoads {
  std::vector<Vec3>& force;   // f_j [N]
  std::vector<Vec3>& couple;  // c_j [N m]
};

// What a wall particle's loads add to the pair terms of the dynamics.
enum class WallTraction {
  dynamics,  // nothing: the reaction to the dynamics' own terms (the stress form)
  // The traction eta G^T . n that the Morris operator leaves out, in its exact value at a rigid
  // no-slip wall, eta n x omega (docs/power.md, "Viscous traction"), through the stress-form pair
  // term with T = eta_i [omega x]^T on both sides: zero on a wall that does not turn.
  rigid_wall,
};

// Needs the state of one rate evaluation (pressures, wall state, viscosities and, stress form,
// viscous stresses). Fluid particles are [0, fluid_count) of the fields; `loads` get one entry
// per particle, zero for fluid particles.
void compute_wall_forces(const Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& gradient_kernel, const Parameters& parameters,
                         WallTraction traction, WallLoads loads);

}  // namespace partimix::sph
