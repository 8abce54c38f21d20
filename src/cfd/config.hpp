#pragma once
// What the `fluid:` and `cfd:` sections and the shared walls say for the grid fluid
// (docs/case-reference.md, "cfd"; docs/cfd.md).
#include <memory>
#include <vector>

#include "cfd/box_sides.hpp"
#include "cfd/fluid_solver.hpp"
#include "cfd/wall_motions.hpp"
#include "geometry/motion.hpp"
#include "geometry/shape.hpp"
#include "geometry/surface.hpp"

namespace partimix::cfd {

struct CfdConfig {
  double cell_size = 0.0;  // the wanted h [m]; each axis takes the nearest whole count of cells
  FluidSettings settings;  // density, rheology, numerics
  BoxSides sides;
  // The surfaces of the case's walls: cells whose centre lies on or behind one are blocked
  // (docs/cfd.md, "Walls: blocked cells"); the walls' motions, each wall's surface staying in
  // place in the fluid's frame (docs/cfd.md, "Moving walls and the rotating frame").
  std::vector<std::shared_ptr<const geometry::Surface>> walls;
  std::vector<std::shared_ptr<const geometry::Shape>> wall_shapes;  // each wall's, or null
  std::vector<std::shared_ptr<const geometry::Motion>> wall_motions;
  InPlaceSamples in_place_samples;
  // With two phases (settings.light_phase), where the heavy phase is at the start: fluid.regions
  // (docs/cfd.md, "Two phases: volume of fluid").
  std::vector<std::shared_ptr<const geometry::Shape>> heavy_regions;
  int frame_wall = -1;  // cfd.rotating_frame.wall: the wall whose body the grid turns with; -1 lab
  double max_cells = 0.0;  // limits.grid_nodes
};

}  // namespace partimix::cfd
