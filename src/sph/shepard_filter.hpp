#pragma once
// Shepard density re-initialisation, the seed's eq. 20 (Colagrossi and Landrini 2003):
// rho_i = sum_j m_j W_ij / sum_j (m_j / rho_j) W_ij over all neighbours, i itself included.
#include <vector>

#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"

namespace partimix::sph {

// `scratch` holds the new densities while the old ones are still read; it is resized once.
void apply_shepard_filter(Fields& fields, const CellGrid& grid, const KernelTable& kernel,
                          std::vector<double>& scratch);

}  // namespace partimix::sph
