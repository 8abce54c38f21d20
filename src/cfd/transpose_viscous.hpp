#pragma once
// The transpose part of a grid fluid's viscous term (docs/cfd.md, "One time step"), explicit:
// on each open face f of component a,
//
//     T_f = Σ_b ∂_b (ε η ∂_a u_b),
//
// b = a from the cells on f's two sides (ε η of the cell, ∂_a u_a from its two faces), b ≠ a
// through the edges f shares with its neighbours along b (ε η the mean of the open cells around
// the edge, ∂_a u_b from the two faces of component b across the edge, whatever they hold: a
// wall's face carries the wall's velocity). With ε η constant, T = ε η ∂_a (∇·u) of the discrete
// divergence, zero after the projection; it matters where ε or η varies.
#include <vector>

#include "cfd/flow_mask.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

// out[a][f] = T_f on the open faces, 0 elsewhere; void_fraction and viscosity per cell.
void transpose_viscous_term(const grid::StaggeredGrid& grid, const FlowMask& mask,
                            const std::vector<double>& void_fraction,
                            const std::vector<double>& viscosity, const FaceArrays& velocity,
                            FaceArrays& out);

}  // namespace partimix::cfd
