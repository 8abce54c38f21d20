#include "coupling/face_weights.hpp"

#include "cfd/face_stencil.hpp"

namespace partimix::coupling {

void FaceWeights::build(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                        const KernelWeights& cells, std::size_t grains) {
  for (int axis = 0; axis < 3; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    start_[a].assign(grains + 1, 0);
    weights_[a].clear();
    if (axis >= grid.dimensions())
      continue;
    for (std::size_t i = 0; i < grains; ++i) {
      add_grain(grid, mask, axis, cells.of(i));
      start_[a][i + 1] = weights_[a].size();
    }
  }
}

// The faces below and above each weighted cell along `axis`, each with half its weight.
void FaceWeights::add_grain(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask, int axis,
                            std::span<const KernelWeights::Weight> cells) {
  std::vector<Weight>& out = weights_[static_cast<std::size_t>(axis)];
  const std::size_t first = out.size();
  double sum = 0.0;
  for (const KernelWeights::Weight& w : cells) {
    const cfd::Coordinates cell = grid.cell_coordinates(w.cell);
    for (const int step : {0, 1}) {
      cfd::Coordinates face = cell;
      face[axis] = grid.wrap_face(axis, cell[axis] + step);
      const std::size_t index = cfd::face_index(grid, axis, face);
      if (!mask.open_face[axis][index])
        continue;
      out.push_back({static_cast<std::uint32_t>(index), 0.5 * w.weight});
      sum += 0.5 * w.weight;
    }
  }
  if (sum > 0.0)
    for (std::size_t e = first; e < out.size(); ++e)
      out[e].weight /= sum;
}

}  // namespace partimix::coupling
