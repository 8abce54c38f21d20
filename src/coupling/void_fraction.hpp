#pragma once
// The void fraction of the grid fluid's cells from the grains (docs/cfd-dem.md, "Void fraction:
// the grains' volume on the grid"): ε_c = 1 - Σ_i V_i w_ic / V_c on the open cells, 1 on the
// closed ones, clipped below at `minimum`. Without clipping Σ_c (1 - ε_c) V_c = Σ_i V_i over the
// mapped grains to round-off, since each grain's weights sum to one.
#include <span>
#include <vector>

#include "coupling/kernel_weights.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::coupling {

// Fills `out` (one value per cell); returns the number of cells clipped.
std::size_t void_fraction(const grid::StaggeredGrid& grid, const KernelWeights& weights,
                          std::span<const double> volumes, double minimum,
                          std::vector<double>& out);

}  // namespace partimix::coupling
