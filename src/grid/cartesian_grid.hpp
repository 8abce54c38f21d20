#pragma once
// The background grid of a grid-based method (DESIGN.md, layer `src/grid`; docs/mpm.md): nodes
// every cell_size over the domain, in 2D one node along z. Along a non-periodic axis the nodes
// reach two cells beyond each face of the domain (ghost nodes, so that the stencil of a point
// inside the domain never leaves the grid); along a periodic axis there are period / cell_size
// nodes and indices wrap.
#include <array>
#include <cstddef>

#include "core/vec.hpp"
#include "particles/domain.hpp"

namespace partimix::grid {

class CartesianGrid {
 public:
  // Throws InputError (no location; the caller names its cell-size key) when a periodic length
  // is not a whole number of cells or the grid would have more than `max_nodes` nodes.
  CartesianGrid(const Domain& domain, double cell_size, double max_nodes);

  int dimensions() const { return dimensions_; }
  double cell_size() const { return h_; }
  int count(int axis) const { return counts_[axis]; }
  std::size_t node_count() const {
    return static_cast<std::size_t>(counts_[0]) * counts_[1] * counts_[2];
  }
  bool periodic(int axis) const { return periodic_[axis]; }

  // Where x lies along `axis`, in cells from node 0.
  double cell_coordinate(int axis, double x) const { return (x - origin_[axis]) / h_; }
  // The coordinate of (unwrapped) node index i along `axis`.
  double coordinate(int axis, int i) const { return origin_[axis] + i * h_; }
  Vec3 node_position(std::size_t node) const;

  // Node index along `axis` of an unwrapped index: wrapped on a periodic axis, -1 outside the
  // grid otherwise.
  int wrap(int axis, int i) const {
    if (periodic_[axis])
      return ((i % counts_[axis]) + counts_[axis]) % counts_[axis];
    return (i >= 0 && i < counts_[axis]) ? i : -1;
  }
  std::size_t linear(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * counts_[1] + j) * counts_[0] + i;
  }

 private:
  int dimensions_;
  double h_;
  Vec3 origin_ = Vec3::Zero();
  std::array<int, 3> counts_{1, 1, 1};
  std::array<bool, 3> periodic_{false, false, false};
};

}  // namespace partimix::grid
