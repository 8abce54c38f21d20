#pragma once
// The shear rate of a grid fluid at its cell centres (docs/cfd.md, "Non-Newtonian viscosity"):
// γ̇ = sqrt(2 D:D), D = (∇u + ∇uᵀ) / 2, with ∂u_a/∂x_a from the cell's two faces of component a
// (exact on the staggered grid) and ∂u_a/∂x_b (b ≠ a) from the cell-centred u_a (the mean of
// its two faces) of the neighbours along b, central, or to a wall half a cell away: the side's
// velocity on a no-slip side, the same value (zero gradient) on a slip or outlet side, the wall's
// velocity on the face of a blocked cell (cfd/wall_faces.hpp; rest for a wall at rest). Closed
// cells get 0.
#include <vector>

#include "cfd/box_sides.hpp"
#include "cfd/flow_mask.hpp"
#include "cfd/wall_faces.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

void cell_shear_rates(const grid::StaggeredGrid& grid, const FlowMask& mask, const BoxSides& sides,
                      const WallFaces& walls, const FaceArrays& velocity, std::vector<double>& out);

}  // namespace partimix::cfd
