#pragma once
// Which cells of a grid fluid hold fluid and which face velocities are unknowns (docs/cfd.md,
// "Walls: blocked cells"): a face is open when the cells on both its sides exist and are open;
// the velocity of any other face (on the box's sides, or against a blocked cell) is set by the
// wall there, but on an outlet side, where the faces of open cells are outlet faces: their
// velocity follows from the pressure correction (cfd/pressure_projection.hpp).
#include <array>
#include <cstdint>
#include <vector>

#include "cfd/box_sides.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

// One value per face normal to each axis (empty for z in 2D).
using FaceArrays = std::array<std::vector<double>, 3>;

struct FlowMask {
  std::vector<std::uint8_t> open_cell;
  std::array<std::vector<std::uint8_t>, 3> open_face;
  std::array<std::vector<std::uint8_t>, 3> outlet_face;
};

// Every cell open; the faces from them.
FlowMask open_mask(const grid::StaggeredGrid& grid);
// The faces' flags from the cells' (no outlet faces).
void open_faces(const grid::StaggeredGrid& grid, FlowMask& mask);
// The faces of open cells on the outlet sides.
void mark_outlets(const grid::StaggeredGrid& grid, const BoxSides& sides, FlowMask& mask);
// Face arrays of the grid's shape, filled with `value`.
FaceArrays face_arrays(const grid::StaggeredGrid& grid, double value);

}  // namespace partimix::cfd
