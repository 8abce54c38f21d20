#pragma once
// The heavy phase's volume fraction α of a two-phase grid fluid (docs/cfd.md, "Two phases:
// volume of fluid"): after the step's projection, in every open cell c,
//
//     ε_c^{n+1} α_c^{n+1} V = ε_c^n α_c^n V - Δt Σ_f ±F_f α_f,    F_f = ε_f u_f^{n+1} A_f,
//
// over all the cell's faces (± outward), the same fluxes whose sum the projection made equal to
// -(ε^{n+1} - ε^n) V / Δt, so that a uniform α stays uniform and Σ ε α V changes only by what
// crosses the box's sides. α_f between two open cells is the upwind value plus Roe's superbee
// limited share of the jump to the downwind one (Sweby 1984), which keeps the interface within
// two or three cells; on an outlet side the inner cell's α leaving and the light phase (0)
// entering; an inlet side brings the heavy phase (1); a wall face, which carries no net flow, its
// open cell's own α. Bounded (0 ≤ α ≤ 1) when each cell's outflow over the step is at most half
// its fluid volume (stable_dt()).
#include <vector>

#include "cfd/flow_mask.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

// Roe's superbee limiter ψ(r) = max(0, min(2r, 1), min(r, 2)).
double superbee(double r);

class PhaseTransport {
 public:
  // The limit on each cell's outflow over a step, as a share of its fluid volume.
  static constexpr double kMostOutflow = 0.5;

  // Advances α (one value per cell, closed cells untouched) over dt. void_fraction: ε_f on every
  // face; old_cells and new_cells: ε_c^n and ε_c^{n+1}.
  void advance(const grid::StaggeredGrid& grid, const FlowMask& mask,
               const FaceArrays& void_fraction, const FaceArrays& velocity,
               const std::vector<double>& old_cells, const std::vector<double>& new_cells,
               double dt, std::vector<double>& fraction);

  // The largest dt for which no open cell's outflow exceeds kMostOutflow of ε_c V.
  double stable_dt(const grid::StaggeredGrid& grid, const FlowMask& mask,
                   const FaceArrays& void_fraction, const FaceArrays& velocity,
                   const std::vector<double>& cells) const;

 private:
  std::vector<double> change_;           // -Δt Σ ±F α_f per cell
  mutable std::vector<double> outflow_;  // stable_dt()'s Σ max(±F, 0) per cell
};

}  // namespace partimix::cfd
