#include "grid/shape_function.hpp"
#include "grid/shape_functions/bspline_shape.hpp"
#include "grid/shape_functions/gimp_shape.hpp"
#include "grid/shape_functions/linear_shape.hpp"

namespace partimix::grid {

const Registry<ShapeFunction, const ShapeFunctionOptions&>& shape_function_registry() {
  static const Registry<ShapeFunction, const ShapeFunctionOptions&> registry = [] {
    Registry<ShapeFunction, const ShapeFunctionOptions&> r;
    r.add("linear", [](const ShapeFunctionOptions&) { return std::make_unique<LinearShape>(); });
    r.add("gimp", [](const ShapeFunctionOptions& o) {
      return std::make_unique<GimpShape>(o.point_half_width);
    });
    r.add("bspline", [](const ShapeFunctionOptions&) { return std::make_unique<BsplineShape>(); });
    return r;
  }();
  return registry;
}

}  // namespace partimix::grid
