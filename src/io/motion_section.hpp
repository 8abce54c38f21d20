#pragma once
// The `motion:` map of a wall (docs/case-reference.md, "walls"): fixed, rotation, planetary or
// translation, shared by the SPH walls and the DEM walls.
#include "geometry/motion.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

geometry::MotionConfig read_motion(Reader& item, int dimensions);

}  // namespace partimix::io
