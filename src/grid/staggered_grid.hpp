#pragma once
// The cells and faces of a grid fluid's staggered (MAC) grid (docs/cfd.md, "The grid: staggered
// (MAC)"): cells of sizes h_x, h_y, h_z over the box [origin, origin + n h); scalars (pressure,
// void fraction) at cell centres, each velocity component at the centres of the faces normal to
// it. Along a non-periodic axis there is one more face than cells (faces 0 and n on the box's
// sides); along a periodic axis n faces, face n being face 0. In 2D the z axis has one cell of
// depth 1 m and no faces normal to it. Cells and faces are numbered x fastest.
#include <array>
#include <cstddef>
#include <cstdint>

#include "core/vec.hpp"

namespace partimix::grid {

class StaggeredGrid {
 public:
  // Throws InputError (no location; the caller names its keys) for fewer than one cell along an
  // axis, a spacing that is not positive, or more than `max_cells` cells.
  StaggeredGrid(int dimensions, const Vec3& origin, const std::array<int, 3>& cells,
                const Vec3& spacing, const std::array<bool, 3>& periodic, double max_cells);

  int dimensions() const { return dimensions_; }
  // The box's lowest corner.
  const Vec3& origin() const { return origin_; }
  int cells(int axis) const { return cells_[axis]; }
  double spacing(int axis) const { return spacing_[axis]; }
  bool periodic(int axis) const { return periodic_[axis]; }
  std::size_t cell_count() const { return cell_count_; }
  double cell_volume() const { return spacing_[0] * spacing_[1] * spacing_[2]; }
  // The area of a face normal to `axis`.
  double face_area(int axis) const { return cell_volume() / spacing_[axis]; }

  std::size_t cell(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * cells_[1] + j) * cells_[0] + i;
  }
  std::array<int, 3> cell_coordinates(std::size_t index) const {
    const auto nx = static_cast<std::size_t>(cells_[0]);
    const auto ny = static_cast<std::size_t>(cells_[1]);
    return {static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
            static_cast<int>(index / (nx * ny))};
  }
  Vec3 cell_centre(int i, int j, int k) const;

  // Faces normal to `axis`: how many along `along`, in all, the index of face (i, j, k) (its
  // coordinate along `axis` is the face's number, those along the other axes the cell's).
  int faces(int axis, int along) const { return face_counts_[axis][along]; }
  std::size_t face_count(int axis) const { return face_totals_[axis]; }
  std::size_t face(int axis, int i, int j, int k) const {
    const std::array<int, 3>& n = face_counts_[axis];
    return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i;
  }
  std::array<int, 3> face_coordinates(int axis, std::size_t index) const {
    const auto nx = static_cast<std::size_t>(face_counts_[axis][0]);
    const auto ny = static_cast<std::size_t>(face_counts_[axis][1]);
    return {static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
            static_cast<int>(index / (nx * ny))};
  }
  Vec3 face_centre(int axis, int i, int j, int k) const;

  // Calls fn(coordinates, index) for every cell, x fastest.
  template <class Fn>
  void for_each_cell(Fn&& fn) const {
    for (int k = 0; k < cells_[2]; ++k)
      for (int j = 0; j < cells_[1]; ++j)
        for (int i = 0; i < cells_[0]; ++i)
          fn(std::array<int, 3>{i, j, k}, cell(i, j, k));
  }
  // Calls fn(coordinates, index) for every face normal to `axis`, x fastest.
  template <class Fn>
  void for_each_face(int axis, Fn&& fn) const {
    const std::array<int, 3>& n = face_counts_[axis];
    if (face_totals_[axis] == 0)
      return;
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
          fn(std::array<int, 3>{i, j, k}, face(axis, i, j, k));
  }

  // Calls fn(axis, face, side, neighbour) for each face of cell (i, j, k): side -1 for the face
  // below the cell along axis, +1 above; neighbour the cell beyond that face, -1 beyond a side
  // of the box.
  template <class Fn>
  void for_each_face_of_cell(int i, int j, int k, Fn&& fn) const {
    const std::array<int, 3> c{i, j, k};
    for (int axis = 0; axis < dimensions_; ++axis) {
      for (const int side : {-1, 1}) {
        std::array<int, 3> f = c;
        f[axis] = wrap_face(axis, c[axis] + (side > 0 ? 1 : 0));
        std::array<int, 3> n = c;
        n[axis] = wrap_cell(axis, c[axis] + side);
        const std::int64_t neighbour =
            n[axis] < 0 ? -1 : static_cast<std::int64_t>(cell(n[0], n[1], n[2]));
        fn(axis, face(axis, f[0], f[1], f[2]), side, neighbour);
      }
    }
  }

  // A cell index along `axis`: wrapped on a periodic axis, -1 outside the grid otherwise.
  int wrap_cell(int axis, int i) const {
    if (periodic_[axis])
      return ((i % cells_[axis]) + cells_[axis]) % cells_[axis];
    return (i >= 0 && i < cells_[axis]) ? i : -1;
  }
  // A face number along its own axis: wrapped on a periodic axis, -1 beyond the sides otherwise.
  int wrap_face(int axis, int i) const {
    if (periodic_[axis])
      return wrap_cell(axis, i);
    return (i >= 0 && i <= cells_[axis]) ? i : -1;
  }

 private:
  int dimensions_;
  Vec3 origin_;
  std::array<int, 3> cells_;
  Vec3 spacing_;
  std::array<bool, 3> periodic_;
  std::size_t cell_count_ = 0;
  std::array<std::array<int, 3>, 3> face_counts_{};
  std::array<std::size_t, 3> face_totals_{};
};

}  // namespace partimix::grid
