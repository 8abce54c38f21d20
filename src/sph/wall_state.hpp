#pragma once
// Generalised wall boundary of Adami, Hu and Adams (2012), eqs. 22-28: every wall particle takes
// the pressure extrapolated from the fluid around it, with the hydrostatic correction, the
// density that pressure implies through the equation of state, and a ghost velocity
// 2 v_wall - v~ that enforces no slip in the viscous term (docs/sph.md, "Walls").
#include "particles/cell_grid.hpp"
#include "sph/equation_of_state.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

// Fluid particles are [0, fluid_count) of the fields, walls the rest.
void update_wall_state(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                       const KernelTable& kernel, const EquationOfState& eos,
                       const Parameters& parameters);

}  // namespace partimix::sph
