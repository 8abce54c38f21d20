#pragma once
// The 1D shape function of a background grid (docs/mpm.md, "Shape functions"): a node's weight
// N(r) for a point r cells away from it, and dN/dr. A grid's shape function is the tensor
// product of the 1D one along each axis (grid/point_stencil.hpp).
#include <memory>

#include "core/registry.hpp"

namespace partimix::grid {

class ShapeFunction {
 public:
  virtual ~ShapeFunction() = default;
  // The weight of a node r cells from the point, and its derivative in r.
  virtual double value(double r) const = 0;
  virtual double slope(double r) const = 0;
  // N(r) = 0 for |r| >= radius() (in cells); at most 3 nodes per axis.
  virtual double radius() const = 0;
  // APIC's inertia D_p / h^2 when it is the same for every point (1/4 for the quadratic
  // B-spline; docs/mpm.md, "Transfers"); 0 when it is not, and APIC takes the gradient form.
  virtual double apic_inertia() const { return 0.0; }
};

// What a shape function may depend on: the half-width of a point in cells (GIMP).
struct ShapeFunctionOptions {
  double point_half_width = 0.25;
};

// Shape functions by name: linear, gimp, bspline (quadratic B-spline).
const Registry<ShapeFunction, const ShapeFunctionOptions&>& shape_function_registry();

}  // namespace partimix::grid
