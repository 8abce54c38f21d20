#include "cfd/flow_mask.hpp"

namespace partimix::cfd {

FlowMask open_mask(const grid::StaggeredGrid& grid) {
  FlowMask mask;
  mask.open_cell.assign(grid.cell_count(), 1);
  open_faces(grid, mask);
  return mask;
}

void open_faces(const grid::StaggeredGrid& grid, FlowMask& mask) {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<std::uint8_t>& open = mask.open_face[axis];
    open.assign(grid.face_count(axis), 0);
    mask.outlet_face[axis].assign(grid.face_count(axis), 0);
    grid.for_each_face(axis, [&](const std::array<int, 3>& f, std::size_t index) {
      std::array<int, 3> below = f;
      std::array<int, 3> above = f;
      below[axis] = grid.wrap_cell(axis, f[axis] - 1);
      above[axis] = grid.wrap_cell(axis, f[axis]);
      if (below[axis] < 0 || above[axis] < 0)
        return;
      open[index] = mask.open_cell[grid.cell(below[0], below[1], below[2])] &&
                    mask.open_cell[grid.cell(above[0], above[1], above[2])];
    });
  }
}

void mark_outlets(const grid::StaggeredGrid& grid, const BoxSides& sides, FlowMask& mask) {
  for (int axis = 0; axis < grid.dimensions(); ++axis) {
    if (grid.periodic(axis))
      continue;
    grid.for_each_face(axis, [&](const std::array<int, 3>& f, std::size_t index) {
      const bool low = f[axis] == 0;
      if (!low && f[axis] != grid.cells(axis))
        return;
      if (!box_side(sides, axis, low ? -1 : 1).outlet)
        return;
      std::array<int, 3> cell = f;
      cell[axis] = low ? 0 : f[axis] - 1;
      mask.outlet_face[axis][index] = mask.open_cell[grid.cell(cell[0], cell[1], cell[2])];
    });
  }
}

FaceArrays face_arrays(const grid::StaggeredGrid& grid, double value) {
  FaceArrays arrays;
  for (int axis = 0; axis < 3; ++axis)
    arrays[axis].assign(grid.face_count(axis), value);
  return arrays;
}

}  // namespace partimix::cfd
