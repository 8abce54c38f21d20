#pragma once
// Shear rate of every fluid particle from the SPH velocity gradient (docs/rheology.md, "Shear
// rate"; the seed's eqs. 5, 6 and 16):
//   G_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij,   S = (G + G^T) / 2,   gamma_dot = sqrt(2 S:S)
// Wall neighbours enter with their no-slip ghost velocity. `corrected` multiplies G by the
// inverse of M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij (Bonet and Lok 1999), which makes the
// gradient exact for linear velocity fields also where the kernel is cut (free surface).
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

// Writes fields.shear_rate for the fluid particles [0, fluid_count).
void compute_shear_rates(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& gradient_kernel, int dimensions, bool corrected);

}  // namespace partimix::sph
