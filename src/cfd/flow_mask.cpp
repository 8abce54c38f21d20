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

FaceArrays face_arrays(const grid::StaggeredGrid& grid, double value) {
  FaceArrays arrays;
  for (int axis = 0; axis < 3; ++axis)
    arrays[axis].assign(grid.face_count(axis), value);
  return arrays;
}

}  // namespace partimix::cfd
