#include "coupling/void_fraction.hpp"

namespace partimix::coupling {

std::size_t void_fraction(const grid::StaggeredGrid& grid, const KernelWeights& weights,
                          std::span<const double> volumes, double minimum,
                          std::vector<double>& out) {
  out.assign(grid.cell_count(), 1.0);
  const double cell_volume = grid.cell_volume();
  for (std::size_t i = 0; i < volumes.size(); ++i)
    for (const KernelWeights::Weight& w : weights.of(i))
      out[w.cell] -= volumes[i] * w.weight / cell_volume;
  std::size_t clipped = 0;
  for (double& eps : out)
    if (eps < minimum) {
      eps = minimum;
      ++clipped;
    }
  return clipped;
}

}  // namespace partimix::coupling
