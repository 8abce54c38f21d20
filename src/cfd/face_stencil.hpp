#pragma once
// Neighbours of a velocity face on the staggered grid (docs/cfd.md, "The grid: staggered
// (MAC)"): the faces of the same component one step along an axis, the cells on a face's two
// sides, and the cells around the edge a face's control volume shares with its neighbour.
// Faces are given by their coordinates (i, j, k); -1 in a coordinate means "beyond the box".
#include <array>
#include <cstddef>
#include <vector>

#include "cfd/flow_mask.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

using Coordinates = std::array<int, 3>;

// The face of component `axis` one step along `along` (side -1 or +1) from face f, wrapped on a
// periodic axis; false beyond the box.
inline bool neighbour_face(const grid::StaggeredGrid& grid, int axis, const Coordinates& f,
                           int along, int side, Coordinates& out) {
  out = f;
  out[along] = along == axis ? grid.wrap_face(axis, f[along] + side)
                             : grid.wrap_cell(along, f[along] + side);
  return out[along] >= 0;
}

// The cell on side -1 (below) or +1 (above) of face f of component `axis`; false beyond the box.
inline bool cell_beside(const grid::StaggeredGrid& grid, int axis, const Coordinates& f, int side,
                        Coordinates& out) {
  out = f;
  out[axis] = grid.wrap_cell(axis, side < 0 ? f[axis] - 1 : f[axis]);
  return out[axis] >= 0;
}

inline std::size_t cell_index(const grid::StaggeredGrid& grid, const Coordinates& c) {
  return grid.cell(c[0], c[1], c[2]);
}

inline std::size_t face_index(const grid::StaggeredGrid& grid, int axis, const Coordinates& f) {
  return grid.face(axis, f[0], f[1], f[2]);
}

// The cell on side -1 or +1 of face f of component `axis` (its index in `cell`); true when it
// exists and is open.
inline bool open_cell_beside(const grid::StaggeredGrid& grid, const FlowMask& mask, int axis,
                             const Coordinates& f, int side, std::size_t& cell) {
  Coordinates c;
  if (!cell_beside(grid, axis, f, side, c) || c[axis] >= grid.cells(axis))
    return false;
  cell = cell_index(grid, c);
  return mask.open_cell[cell] != 0;
}

// (q_above - q_below) / h of a cell field q across face f of component `axis`, whose cells on
// both sides exist.
inline double gradient_across(const grid::StaggeredGrid& grid, int axis, const Coordinates& f,
                              const std::vector<double>& q) {
  Coordinates below;
  Coordinates above;
  cell_beside(grid, axis, f, -1, below);
  cell_beside(grid, axis, f, 1, above);
  return (q[cell_index(grid, above)] - q[cell_index(grid, below)]) / grid.spacing(axis);
}

}  // namespace partimix::cfd
