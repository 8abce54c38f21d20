#pragma once
// Points sorted by the lowest node of their stencil, and the nodes any point touches
// (docs/mpm.md, "Parallel loops and determinism"): the particle-to-grid transfer is then a
// gather, each node summing the points of the buckets that reach it in a fixed order, so that
// its result does not depend on the thread count. Rebuilt every step; the arrays are kept.
#include <cstdint>
#include <span>
#include <vector>

#include "grid/cartesian_grid.hpp"
#include "grid/point_stencil.hpp"

namespace partimix::grid {

class NodeBuckets {
 public:
  void build(const CartesianGrid& grid, std::span<const PointStencil> stencils);

  // The points whose stencil starts at `node`, in index order.
  std::span<const std::uint32_t> points(std::size_t node) const {
    return {order_.data() + start_[node], order_.data() + start_[node + 1]};
  }
  // Every node some point's stencil covers, ascending.
  const std::vector<std::size_t>& active_nodes() const { return active_; }

  // Calls f(point, a, b, c) for every point whose stencil covers `node`, where (a, b, c) is the
  // node's place in the point's stencil, in a fixed order.
  template <class F>
  void for_each_point(const CartesianGrid& grid, std::size_t node, F&& f) const;

 private:
  void mark_active(const CartesianGrid& grid, std::span<const PointStencil> stencils);

  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint8_t> touched_;
  std::vector<std::size_t> active_;
  std::array<int, 3> span_{1, 1, 1};  // nodes per axis of every stencil
};

template <class F>
void NodeBuckets::for_each_point(const CartesianGrid& grid, std::size_t node, F&& f) const {
  const int i = static_cast<int>(node % grid.count(0));
  const int j = static_cast<int>((node / grid.count(0)) % grid.count(1));
  const int k = static_cast<int>(node / (static_cast<std::size_t>(grid.count(0)) * grid.count(1)));
  for (int c = 0; c < span_[2]; ++c) {
    const int kk = grid.wrap(2, k - c);
    if (kk < 0)
      continue;
    for (int b = 0; b < span_[1]; ++b) {
      const int jj = grid.wrap(1, j - b);
      if (jj < 0)
        continue;
      for (int a = 0; a < span_[0]; ++a) {
        const int ii = grid.wrap(0, i - a);
        if (ii < 0)
          continue;
        for (const std::uint32_t p : points(grid.linear(ii, jj, kk)))
          f(p, a, b, c);
      }
    }
  }
}

}  // namespace partimix::grid
