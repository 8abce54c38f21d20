#include "grid/cartesian_grid.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::grid {
namespace {

constexpr int kGhostLayers = 2;

}  // namespace

CartesianGrid::CartesianGrid(const Domain& domain, double cell_size, double max_nodes)
    : dimensions_(domain.dimensions), h_(cell_size) {
  static const char* const names[] = {"x", "y", "z"};
  double nodes = 1.0;
  for (int axis = 0; axis < dimensions_; ++axis) {
    const double cells = domain.length()[axis] / h_;
    periodic_[axis] = domain.periodic[axis];
    double count = 0.0;
    if (periodic_[axis]) {
      count = std::round(cells);
      if (count < 3.0 || std::abs(cells - count) > 1e-6 * cells) {
        throw InputError(
            {},
            fmt::format("the domain's periodic length along {} ({:.6g} m) must be a whole number "
                        "of at least 3 cells of {:.6g} m",
                        names[axis], domain.length()[axis], h_));
      }
      origin_[axis] = domain.lo[axis];
    } else {
      count = std::ceil(cells - 1e-9) + 1.0 + 2.0 * kGhostLayers;
      origin_[axis] = domain.lo[axis] - kGhostLayers * h_;
    }
    nodes *= count;
    if (!(nodes <= max_nodes)) {
      throw InputError({}, fmt::format("a grid of {:.6g} m cells over the domain has more than "
                                       "limits.grid_nodes = {:.3g} nodes",
                                       h_, max_nodes));
    }
    counts_[axis] = static_cast<int>(count);
  }
}

Vec3 CartesianGrid::node_position(std::size_t node) const {
  const std::size_t i = node % counts_[0];
  const std::size_t j = (node / counts_[0]) % counts_[1];
  const std::size_t k = node / (static_cast<std::size_t>(counts_[0]) * counts_[1]);
  Vec3 x =
      origin_ + h_ * Vec3(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k));
  if (dimensions_ == 2)
    x.z() = 0.0;
  return x;
}

}  // namespace partimix::grid
