#include "cfd/blocked_cells.hpp"

#include <algorithm>

namespace partimix::cfd {

FlowMask blocked_by_walls(const grid::StaggeredGrid& grid,
                          std::span<const std::shared_ptr<const geometry::Surface>> walls) {
  FlowMask mask = open_mask(grid);
  double h = 0.0;
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    h = std::max(h, grid.spacing(axis));
  // A surface answers only within reach on its material side; behind it, always.
  const double reach = h;
  grid.for_each_cell([&](const std::array<int, 3>& c, std::size_t index) {
    const Vec3 centre = grid.cell_centre(c[0], c[1], c[2]);
    for (const auto& wall : walls) {
      geometry::SurfacePoint point;
      // A centre on the surface is blocked: round-off in its coordinate must not decide.
      if (wall->nearest(centre, reach, point) && point.gap <= 1e-9 * h) {
        mask.open_cell[index] = 0;
        break;
      }
    }
  });
  open_faces(grid, mask);
  return mask;
}

}  // namespace partimix::cfd
