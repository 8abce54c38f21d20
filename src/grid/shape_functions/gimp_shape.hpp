#pragma once
// Uniform GIMP shape function for a point of half-width l cells (docs/mpm.md, "Shape functions";
// Bardenhagen & Kober 2004, eq. 40): linear away from the node, smoothed where the point's
// extent overlaps a node or the edge of the node's support.
#include <cmath>

#include "grid/shape_function.hpp"

namespace partimix::grid {

class GimpShape final : public ShapeFunction {
 public:
  explicit GimpShape(double half_width) : l_(half_width) {}
  double value(double r) const override {
    const double a = std::abs(r);
    if (a < l_)
      return 1.0 - (r * r + l_ * l_) / (2.0 * l_);
    if (a < 1.0 - l_)
      return 1.0 - a;
    if (a < 1.0 + l_)
      return (1.0 + l_ - a) * (1.0 + l_ - a) / (4.0 * l_);
    return 0.0;
  }
  double slope(double r) const override {
    const double a = std::abs(r);
    const double sign = r > 0.0 ? 1.0 : -1.0;
    if (a < l_)
      return -r / l_;
    if (a < 1.0 - l_)
      return -sign;
    if (a < 1.0 + l_)
      return -sign * (1.0 + l_ - a) / (2.0 * l_);
    return 0.0;
  }
  double radius() const override { return 1.0 + l_; }

 private:
  double l_;
};

}  // namespace partimix::grid
