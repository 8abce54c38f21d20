#pragma once
// A truck drum wall (docs/case-reference.md, "Shapes", truck_drum; docs/truck-drum.md): its
// placement, the shell's dimensions and a `blades` map with the angles in degrees.
#include <memory>

#include "geometry/shape.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

std::shared_ptr<const geometry::Shape> read_truck_drum(Reader& item, int dimensions);

}  // namespace partimix::io
