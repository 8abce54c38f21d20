#pragma once
// The discrete continuity equation of a grid fluid (docs/cfd.md, "One time step"): in each open
// cell c, Σ_f ±ε_f u_f A_f / V_c + s_c, the outward flux of fluid volume per unit volume plus
// the rate s = Δε/Δt at which the fluid's share of the cell changes [1/s].
#include <vector>

#include "cfd/flow_mask.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

// Σ_f ±ε_f u_f A_f over the faces of cell (i, j, k): the fluid volume leaving it per second.
double cell_outflow(const grid::StaggeredGrid& grid, int i, int j, int k,
                    const FaceArrays& void_fraction, const FaceArrays& velocity);

// The largest |residual| over the open cells.
double continuity_residual(const grid::StaggeredGrid& grid, const FlowMask& mask,
                           const FaceArrays& void_fraction, const FaceArrays& velocity,
                           const std::vector<double>& source);

}  // namespace partimix::cfd
