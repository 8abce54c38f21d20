#include "grid/node_buckets.hpp"

namespace partimix::grid {
namespace {

std::size_t base_node(const CartesianGrid& grid, const PointStencil& s) {
  return grid.linear(grid.wrap(0, s[0].base), grid.wrap(1, s[1].base), grid.wrap(2, s[2].base));
}

}  // namespace

// A counting sort of the points by their base node (stable: index order within a bucket), then
// the nodes their stencils cover. The arrays keep their capacity between steps.
void NodeBuckets::build(const CartesianGrid& grid, std::span<const PointStencil> stencils) {
  const std::size_t nodes = grid.node_count();
  start_.assign(nodes + 1, 0);
  order_.resize(stencils.size());
  for (int axis = 0; axis < 3; ++axis)
    span_[axis] = stencils.empty() ? 1 : stencils.front()[axis].count;
  for (const PointStencil& s : stencils)
    ++start_[base_node(grid, s) + 1];
  for (std::size_t n = 0; n < nodes; ++n)
    start_[n + 1] += start_[n];
  for (std::uint32_t p = 0; p < stencils.size(); ++p)
    order_[start_[base_node(grid, stencils[p])]++] = p;
  // start_[n] now ends bucket n: shift by one bucket.
  for (std::size_t n = nodes; n > 0; --n)
    start_[n] = start_[n - 1];
  start_[0] = 0;
  mark_active(grid, stencils);
}

void NodeBuckets::mark_active(const CartesianGrid& grid, std::span<const PointStencil> stencils) {
  touched_.assign(grid.node_count(), 0);
  for (std::size_t bucket = 0; bucket < grid.node_count(); ++bucket) {
    if (start_[bucket + 1] == start_[bucket])
      continue;  // the points of one bucket share their stencil's nodes: mark them once
    for_each_node(grid, stencils[order_[start_[bucket]]],
                  [&](std::size_t node, const NodeWeight&) { touched_[node] = 1; });
  }
  active_.clear();
  for (std::size_t n = 0; n < touched_.size(); ++n) {
    if (touched_[n] != 0)
      active_.push_back(n);
  }
}

}  // namespace partimix::grid
