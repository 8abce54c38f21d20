#pragma once
// The nodes a material point touches and their weights (docs/mpm.md, "Shape functions"): per
// axis the lowest node `base` and, for its `count` nodes base + k, the weight N(r) and its
// derivative dN/dx [1/m]; the node's weight is the product over the axes. In 2D the z axis has
// one node of weight 1.
#include <array>
#include <cmath>

#include "core/vec.hpp"
#include "grid/cartesian_grid.hpp"
#include "grid/shape_function.hpp"

namespace partimix::grid {

struct AxisStencil {
  int base = 0;
  int count = 1;
  double offset = 0.0;  // (node base - point) in cells: node base + k is (offset + k) h away
  std::array<double, 3> weight{1.0, 0.0, 0.0};
  std::array<double, 3> slope{0.0, 0.0, 0.0};  // dN/dx [1/m]
};

using PointStencil = std::array<AxisStencil, 3>;

// Nodes per axis of a shape function: those within its radius of any point.
inline int nodes_per_axis(const ShapeFunction& shape) {
  return static_cast<int>(std::ceil(2.0 * shape.radius() - 1e-12));
}

inline AxisStencil axis_stencil(const ShapeFunction& shape, double cell_coordinate,
                                double cell_size, int count) {
  AxisStencil axis;
  axis.base = static_cast<int>(std::floor(cell_coordinate - shape.radius() + 1.0));
  axis.count = count;
  axis.offset = axis.base - cell_coordinate;
  for (int k = 0; k < count; ++k) {
    const double r = -(axis.offset + k);  // point - node, in cells
    axis.weight[k] = shape.value(r);
    axis.slope[k] = shape.slope(r) / cell_size;
  }
  return axis;
}

inline PointStencil point_stencil(const ShapeFunction& shape, const CartesianGrid& grid,
                                  const Vec3& x) {
  PointStencil stencil;
  const int count = nodes_per_axis(shape);
  for (int axis = 0; axis < grid.dimensions(); ++axis) {
    stencil[axis] =
        axis_stencil(shape, grid.cell_coordinate(axis, x[axis]), grid.cell_size(), count);
  }
  return stencil;
}

// What a point sees of the node (a, b, c) of its stencil: the weight, its gradient [1/m] and
// the node's position relative to the point [m].
struct NodeWeight {
  double weight;
  Vec3 gradient;
  Vec3 offset;
};

inline NodeWeight node_weight(const PointStencil& s, int a, int b, int c, double h) {
  const double wx = s[0].weight[a];
  const double wy = s[1].weight[b];
  const double wz = s[2].weight[c];
  return {wx * wy * wz,
          Vec3(s[0].slope[a] * wy * wz, wx * s[1].slope[b] * wz, wx * wy * s[2].slope[c]),
          Vec3(h * (s[0].offset + a), h * (s[1].offset + b), h * (s[2].offset + c))};
}

// Calls f(node, NodeWeight) for every node of the stencil. The point must lie inside the grid
// (its domain): every node of its stencil exists.
template <class F>
void for_each_node(const CartesianGrid& grid, const PointStencil& s, F&& f) {
  for (int c = 0; c < s[2].count; ++c) {
    const int k = grid.wrap(2, s[2].base + c);
    for (int b = 0; b < s[1].count; ++b) {
      const int j = grid.wrap(1, s[1].base + b);
      for (int a = 0; a < s[0].count; ++a)
        f(grid.linear(grid.wrap(0, s[0].base + a), j, k),
          node_weight(s, a, b, c, grid.cell_size()));
    }
  }
}

}  // namespace partimix::grid
