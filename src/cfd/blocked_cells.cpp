#include "cfd/blocked_cells.hpp"

#include <algorithm>
#include <optional>

namespace partimix::cfd {

namespace {

// What the wall's shape says of the cell at x, if it says anything.
std::optional<bool> shape_blocks(std::span<const std::shared_ptr<const geometry::Shape>> shapes,
                                 std::size_t w, const Vec3& x, double h) {
  if (w >= shapes.size() || shapes[w] == nullptr)
    return std::nullopt;
  return shapes[w]->blocks_grid_cell(x, h);
}

}  // namespace

BlockedCells blocked_by_walls(const grid::StaggeredGrid& grid,
                              std::span<const std::shared_ptr<const geometry::Surface>> walls,
                              std::span<const std::shared_ptr<const geometry::Shape>> shapes) {
  BlockedCells blocked{open_mask(grid), std::vector<std::int32_t>(grid.cell_count(), -1)};
  double h = 0.0;
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    h = std::max(h, grid.spacing(axis));
  // A surface answers only within reach on its material side; behind it, always.
  const double reach = h;
  grid.for_each_cell([&](const std::array<int, 3>& c, std::size_t index) {
    const Vec3 centre = grid.cell_centre(c[0], c[1], c[2]);
    for (std::size_t w = 0; w < walls.size(); ++w) {
      geometry::SurfacePoint point;
      // A centre on the surface is blocked: round-off in its coordinate must not decide.
      const std::optional<bool> by_shape = shape_blocks(shapes, w, centre, h);
      const bool closed =
          by_shape ? *by_shape : walls[w]->nearest(centre, reach, point) && point.gap <= 1e-9 * h;
      if (closed) {
        blocked.mask.open_cell[index] = 0;
        blocked.wall[index] = static_cast<std::int32_t>(w);
        break;
      }
    }
  });
  open_faces(grid, blocked.mask);
  return blocked;
}

}  // namespace partimix::cfd
