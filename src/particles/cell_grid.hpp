#pragma once
// Uniform cell-linked list (DESIGN.md, "Data and speed"): cells at least half an interaction
// radius wide; a particle gathers from the 5 x 5 x 5 (3D) or 5 x 5 (2D) cells around its own,
// which covers 58% of the volume that 27 cells one radius wide cover, so fewer candidates fail
// the distance test (docs/performance.md, "Neighbour search"). Built each step by a counting
// sort into buffers that are reused, so building does not allocate once sized.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "particles/domain.hpp"

namespace partimix {

class CellGrid {
 public:
  // Cells per interaction radius: the stencil reaches this many cells to each side.
  static constexpr int kReach = 2;

  // radius: the interaction radius (kernel support). Throws InputError at key domain.periodic
  // when a periodic axis is shorter than three radii, where the stencil would meet itself.
  // Cells may be wider than radius / kReach so that there are at most 2^24 of them, nor more
  // than 16 per particle, the count rounded up to a power of two (laid out again in build() when
  // the count crosses one).
  CellGrid(const Domain& domain, double radius);

  void build(std::span<const Vec3> positions);

  // Particle indices sorted by cell: new_to_old for ParticleStore::reorder.
  std::span<const std::uint32_t> cell_order() const { return sorted_; }

  double radius() const { return radius_; }
  const std::array<int, 3>& cells_per_axis() const { return cells_; }

  // Calls fn(j, r_ij, r2) for every particle above <= j < below (i itself included when in
  // that range) with r2 = |r_ij|^2 < radius^2, where r_ij = x_i - x_j through the nearest
  // periodic image. Particles outside the range are skipped without reading their positions.
  template <class Fn>
  void for_each_neighbour(std::size_t i, std::span<const Vec3> positions, Fn&& fn,
                          std::size_t below = std::numeric_limits<std::size_t>::max(),
                          std::size_t above = 0) const;

  std::size_t bytes() const;

 private:
  int cell_coordinate(double x, int axis) const;
  void lay_out(double most);
  // Brings a neighbour cell coordinate into the grid across a periodic axis, setting the shift
  // of the image; false when it lies outside a non-periodic axis.
  bool wrap(int& c, int axis, double& shift) const {
    if (c >= 0 && c < cells_[axis])
      return true;
    if (!domain_.periodic[axis])
      return false;
    shift = c < 0 ? periodic_length_[axis] : -periodic_length_[axis];
    c = c < 0 ? c + cells_[axis] : c - cells_[axis];
    return true;
  }
  std::size_t flat(int cx, int cy, int cz) const {
    return (static_cast<std::size_t>(cz) * cells_[1] + cy) * cells_[0] + cx;
  }

  Domain domain_;
  double radius_;
  std::array<double, 3> wanted_{1.0, 1.0, 1.0};  // cells per axis at radius / kReach
  double most_ = 0.0;                            // the bound the cells were laid out for
  std::array<int, 3> cells_{1, 1, 1};
  Vec3 cell_size_;
  Vec3 periodic_length_;
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> sorted_;
};

template <class Fn>
void CellGrid::for_each_neighbour(std::size_t i, std::span<const Vec3> positions, Fn&& fn,
                                  std::size_t below, std::size_t above) const {
  const Vec3& xi = positions[i];
  const double radius2 = radius_ * radius_;
  // Visits the particles of sorted_[first, last) that lie within the radius of i.
  auto visit = [&](std::uint32_t first, std::uint32_t last, double shift_x, double shift_y,
                   double shift_z) {
    const Vec3 shifted = xi + Vec3(shift_x, shift_y, shift_z);
    for (std::uint32_t k = first; k < last; ++k) {
      const std::uint32_t j = sorted_[k];
      if (j >= below || j < above)
        continue;
      const Vec3 rij = shifted - positions[j];
      const double r2 = rij.squaredNorm();
      if (r2 < radius2)
        fn(static_cast<std::size_t>(j), rij, r2);
    }
  };
  // The cells from .. to of one row (x) are adjacent in the sorted order: one range.
  auto visit_row = [&](int from, int to, int cy, int cz, double shift_x, double shift_y,
                       double shift_z) {
    visit(cell_start_[flat(from, cy, cz)], cell_start_[flat(to, cy, cz) + 1], shift_x, shift_y,
          shift_z);
  };
  const int hx = cell_coordinate(xi[0], 0);
  const int hy = cell_coordinate(xi[1], 1);
  const int hz = cell_coordinate(xi[2], 2);
  const int reach_z = domain_.dimensions == 3 ? kReach : 0;
  const int last_x = cells_[0] - 1;
  for (int dz = -reach_z; dz <= reach_z; ++dz) {
    int cz = hz + dz;
    double shift_z = 0.0;
    if (!wrap(cz, 2, shift_z))
      continue;
    for (int dy = -kReach; dy <= kReach; ++dy) {
      int cy = hy + dy;
      double shift_y = 0.0;
      if (!wrap(cy, 1, shift_y))
        continue;
      visit_row(std::max(hx - kReach, 0), std::min(hx + kReach, last_x), cy, cz, 0.0, shift_y,
                shift_z);
      if (!domain_.periodic[0])
        continue;
      if (hx - kReach < 0)
        visit_row(cells_[0] + hx - kReach, last_x, cy, cz, periodic_length_[0], shift_y, shift_z);
      if (hx + kReach > last_x)
        visit_row(0, hx + kReach - cells_[0], cy, cz, -periodic_length_[0], shift_y, shift_z);
    }
  }
}

}  // namespace partimix
