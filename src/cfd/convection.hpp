#pragma once
// The convective term of a grid fluid's momentum equation (docs/cfd.md, "Convection: upwind or
// TVD"): for each open face f of component a,
//
//     C_f = (1/V) Σ_s s m_s φ_s
//
// over the faces of f's control volume, s = -1 or +1 the side along each axis, m_s the mass
// flux through that face in the axis's direction (ρ times the mean of the two continuity fluxes
// ε u of the faces it lies between, so that C is consistent with the discrete continuity
// equation) and φ_s the advected component there: the upwind value, or with `tvd` the upwind
// value plus van Leer's limited share of the jump to the downwind one (Sweby 1984). Where the
// node beyond the upwind one does not exist the face takes the upwind value. Where f's control
// volume reaches a side of the box, φ there is the side's: an outlet's the face's own (zero
// gradient), a wall's or an inlet's its velocity. Explicit.
#include <vector>

#include "cfd/box_sides.hpp"
#include "cfd/flow_mask.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

enum class ConvectionScheme { upwind, tvd };

// out[a][f] = C_f on the open faces, 0 elsewhere; void_fraction: ε on every face.
void convective_term(const grid::StaggeredGrid& grid, const FlowMask& mask, const BoxSides& sides,
                     ConvectionScheme scheme, double density, const FaceArrays& void_fraction,
                     const FaceArrays& velocity, FaceArrays& out);

// van Leer's limiter ψ(r) = (r + |r|) / (1 + |r|).
inline double van_leer(double r) {
  const double a = r < 0.0 ? -r : r;
  return (r + a) / (1.0 + a);
}

}  // namespace partimix::cfd
