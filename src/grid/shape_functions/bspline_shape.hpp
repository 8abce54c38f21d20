#pragma once
// Quadratic B-spline shape function (docs/mpm.md, "Shape functions"; Steffen, Kirby & Berzins
// 2008): C1, so a point crossing a cell face changes no nodal force abruptly. The default.
#include <cmath>

#include "grid/shape_function.hpp"

namespace partimix::grid {

class BsplineShape final : public ShapeFunction {
 public:
  double value(double r) const override {
    const double a = std::abs(r);
    if (a < 0.5)
      return 0.75 - r * r;
    if (a < 1.5)
      return 0.5 * (1.5 - a) * (1.5 - a);
    return 0.0;
  }
  double slope(double r) const override {
    const double a = std::abs(r);
    if (a < 0.5)
      return -2.0 * r;
    if (a < 1.5)
      return (r > 0.0 ? -1.0 : 1.0) * (1.5 - a);
    return 0.0;
  }
  double radius() const override { return 1.5; }
  double apic_inertia() const override { return 0.25; }
};

}  // namespace partimix::grid
