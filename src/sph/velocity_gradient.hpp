#pragma once
// SPH velocity gradient of one fluid particle (docs/rheology.md, "Shear rate"; the seed's
// eq. 16):
//   G_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij
// Wall neighbours enter with their no-slip ghost velocity (Adami et al. 2012).
// `corrected` multiplies G by the inverse of M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij (Bonet
// and Lok 1999), which makes the gradient exact for linear velocity fields also where the kernel
// is cut (free surface).
#include <cmath>
#include <cstddef>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"

namespace partimix::sph {

Mat3 velocity_gradient(std::size_t i, const Fields& fields, const CellGrid& grid,
                       const KernelTable& gradient_kernel, int dimensions, bool corrected);

// gamma_dot = sqrt(2 S:S) of the strain rate S = (G + G^T) / 2 (seed eqs. 5-6).
inline double shear_rate_of(const Mat3& strain_rate) {
  return std::sqrt(2.0 * strain_rate.squaredNorm());
}

}  // namespace partimix::sph
