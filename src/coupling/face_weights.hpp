#pragma once
// The weights w_if by which a grain's force is spread to, and the fluid's velocity and pressure
// gradient gathered from, the open faces of each velocity component (docs/cfd-dem.md, "The
// source S_p and momentum exchanged to round-off"): each cell weight w_ic gives half to each of
// the cell's two faces along the component's axis, and the grain's weights on the open faces are
// normalised to sum to one. Then Σ_f w_if = 1 per component (the force leaves the grain whole),
// and where every face is open (away from walls) the faces' weights are exactly the mean of the
// two cells', which makes the grains' pressure-gradient force the adjoint of the fluid's
// -ε_f ∇p with ε_f the mean of the cells (momentum kept to round-off). A grain whose cells have
// no open face along an axis has no weights there. Compressed rows reused, no allocation once
// sized.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cfd/flow_mask.hpp"
#include "coupling/kernel_weights.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::coupling {

class FaceWeights {
 public:
  struct Weight {
    std::uint32_t face;
    double weight;
  };

  void build(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask, const KernelWeights& cells,
             std::size_t grains);

  // The weights of grain i on the faces normal to `axis`.
  std::span<const Weight> of(int axis, std::size_t i) const {
    const auto a = static_cast<std::size_t>(axis);
    return {weights_[a].data() + start_[a][i], start_[a][i + 1] - start_[a][i]};
  }

 private:
  void add_grain(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask, int axis,
                 std::span<const KernelWeights::Weight> cells);

  std::array<std::vector<std::size_t>, 3> start_;
  std::array<std::vector<Weight>, 3> weights_;
};

}  // namespace partimix::coupling
