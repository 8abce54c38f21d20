#pragma once
// Shear rate gamma_dot = sqrt(2 S:S) of every fluid particle from its SPH velocity gradient
// (sph/velocity_gradient.hpp; docs/rheology.md, "Shear rate"; the seed's eqs. 5, 6 and 16).
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"

namespace partimix::sph {

// Writes fields.shear_rate for the fluid particles [0, fluid_count).
void compute_shear_rates(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& gradient_kernel, int dimensions, bool corrected);

}  // namespace partimix::sph
