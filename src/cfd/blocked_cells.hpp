#pragma once
// The cells of a grid fluid that walls block (docs/cfd.md, "Walls: blocked cells"): a cell is
// blocked when its centre lies on or behind the surface of a wall (the staircase
// representation), or for a wall whose shape decides itself (Shape::blocks_grid_cell: the truck
// drum, outside its cavity short of the opening or within half a cell of a blade) as the shape
// says; the faces' flags follow from the cells' (cfd/flow_mask.hpp).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "cfd/flow_mask.hpp"
#include "geometry/shape.hpp"
#include "geometry/surface.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

struct BlockedCells {
  FlowMask mask;
  std::vector<std::int32_t> wall;  // per cell: the index of the wall that blocks it, -1 open
};

// shapes: each wall's shape, or null (then its surface alone decides).
BlockedCells blocked_by_walls(const grid::StaggeredGrid& grid,
                              std::span<const std::shared_ptr<const geometry::Surface>> walls,
                              std::span<const std::shared_ptr<const geometry::Shape>> shapes);

}  // namespace partimix::cfd
