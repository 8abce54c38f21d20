#pragma once
// Interface compression of the heavy phase's fraction α (docs/cfd.md, "Two phases: interface
// compression"), after the step's transport: across each face between two open cells, a volume
// of heavy phase moves up the gradient of α, from the donor cell d (lower α side) to the acceptor
// cell a, and as much light phase the other way,
//
//     q_f = λ_f Δt c_α |ε_f u_f| A_f |n_f| α_d (1 - α_a),    n_f = (∇α / |∇α|)_f · e_f,
//
// the compressive flux c_α |u| n α (1 - α) of Weller's interface compression (Rusche 2002, §2.3;
// OpenFOAM's interFoam) taken from the donor's α and the acceptor's room (1 - α), so that the
// step is bounded (0 <= α <= 1) when each cell's compressive exchanges over the step are at most
// half its fluid volume, which λ_f <= 1 ensures (the least of its two cells' shares). Where the
// fluid does not move relative to the grid, or α is 0 or 1, nothing moves. Σ ε α V is kept to
// round-off: each q_f leaves one cell and enters the other.
#include <vector>

#include "cfd/flow_mask.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

class InterfaceCompression {
 public:
  // The limit on each cell's compressive exchanges over a step, as a share of its fluid volume.
  static constexpr double kMostExchange = 0.5;

  explicit InterfaceCompression(double coefficient) : coefficient_(coefficient) {}

  // Compresses α (one value per cell, closed cells untouched) over dt. void_fraction: ε_f on
  // every face; cells: ε_c.
  void apply(const grid::StaggeredGrid& grid, const FlowMask& mask, const FaceArrays& void_fraction,
             const FaceArrays& velocity, const std::vector<double>& cells, double dt,
             std::vector<double>& fraction);

 private:
  double coefficient_;             // c_α
  FaceArrays rate_;                // c_α |ε_f u_f| A_f |n_f| [m³/s]; its sign: + where α rises
  std::vector<double> exchange_;   // Σ_f |rate_f| per cell
  std::vector<double> share_;      // λ per cell
  std::vector<double> change_;     // Σ ±q_f per cell
  std::vector<double> gradients_;  // ∇α per cell, three per cell

  void cell_gradients(const grid::StaggeredGrid& grid, const FlowMask& mask,
                      const std::vector<double>& fraction);
  void face_rates(const grid::StaggeredGrid& grid, const FlowMask& mask,
                  const FaceArrays& void_fraction, const FaceArrays& velocity,
                  const std::vector<double>& fraction);
};

}  // namespace partimix::cfd
