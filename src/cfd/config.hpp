#pragma once
// What the `fluid:` and `cfd:` sections and the shared walls say for the grid fluid
// (docs/case-reference.md, "cfd"; docs/cfd.md).
#include <memory>
#include <vector>

#include "cfd/box_sides.hpp"
#include "cfd/fluid_solver.hpp"
#include "geometry/surface.hpp"

namespace partimix::cfd {

struct CfdConfig {
  double cell_size = 0.0;  // the wanted h [m]; each axis takes the nearest whole count of cells
  FluidSettings settings;  // density, rheology, numerics
  BoxSides sides;
  // The surfaces of the case's walls (all fixed): cells whose centre lies on or behind one are
  // blocked (docs/cfd.md, "Walls: blocked cells").
  std::vector<std::shared_ptr<const geometry::Surface>> walls;
  double max_cells = 0.0;  // limits.grid_nodes
};

}  // namespace partimix::cfd
