#include "grid/staggered_grid.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::grid {

StaggeredGrid::StaggeredGrid(int dimensions, const Vec3& origin, const std::array<int, 3>& cells,
                             const Vec3& spacing, const std::array<bool, 3>& periodic,
                             double max_cells)
    : dimensions_(dimensions),
      origin_(origin),
      cells_(cells),
      spacing_(spacing),
      periodic_(periodic) {
  static const char* const names[] = {"x", "y", "z"};
  if (dimensions_ == 2) {
    cells_[2] = 1;
    spacing_[2] = 1.0;
    periodic_[2] = false;
    origin_[2] = -0.5;
  }
  double total = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const int least = periodic_[axis] ? 2 : 1;
    if (cells_[axis] < least || !(spacing_[axis] > 0.0)) {
      throw InputError({}, fmt::format("the grid needs at least {} cells of a positive size along "
                                       "{} (has {} of {:.6g} m)",
                                       least, names[axis], cells_[axis], spacing_[axis]));
    }
    total *= cells_[axis];
  }
  if (!(total <= max_cells)) {
    throw InputError({}, fmt::format("the grid has {:.6g} cells, more than the limit of {:.3g}",
                                     total, max_cells));
  }
  cell_count_ = static_cast<std::size_t>(total);
  for (int axis = 0; axis < 3; ++axis) {
    face_counts_[axis] = cells_;
    const bool has_faces = axis < dimensions_;
    if (has_faces && !periodic_[axis])
      face_counts_[axis][axis] += 1;
    face_totals_[axis] = has_faces ? static_cast<std::size_t>(face_counts_[axis][0]) *
                                         face_counts_[axis][1] * face_counts_[axis][2]
                                   : 0;
  }
}

Vec3 StaggeredGrid::cell_centre(int i, int j, int k) const {
  return origin_ + Vec3((i + 0.5) * spacing_[0], (j + 0.5) * spacing_[1], (k + 0.5) * spacing_[2]);
}

Vec3 StaggeredGrid::face_centre(int axis, int i, int j, int k) const {
  Vec3 centre = cell_centre(i, j, k);
  centre[axis] -= 0.5 * spacing_[axis];
  return centre;
}

}  // namespace partimix::grid
