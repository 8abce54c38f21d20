#pragma once
// Linear (tent) shape function, N = 1 - |r| (docs/mpm.md, "Shape functions"; Sulsky et al.
// 1994). Its slope jumps at the nodes: the cell-crossing error.
#include <cmath>

#include "grid/shape_function.hpp"

namespace partimix::grid {

class LinearShape final : public ShapeFunction {
 public:
  double value(double r) const override {
    const double a = std::abs(r);
    return a < 1.0 ? 1.0 - a : 0.0;
  }
  // One-sided at the kinks, as the stencil sees them (r in [-1, 1) from its nodes), so that the
  // slopes of a point's nodes always sum to zero.
  double slope(double r) const override {
    if (r >= 0.0 && r < 1.0)
      return -1.0;
    if (r < 0.0 && r >= -1.0)
      return 1.0;
    return 0.0;
  }
  double radius() const override { return 1.0; }
};

}  // namespace partimix::grid
