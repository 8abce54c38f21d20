#pragma once
// Uniform cell-linked list (DESIGN.md, "Data and speed"): cells at least one interaction radius
// wide; a particle gathers from the 27 (3D) or 9 (2D) cells around its own. Built each step by a
// counting sort into buffers that are reused, so building does not allocate once sized.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "particles/domain.hpp"

namespace partimix {

class CellGrid {
 public:
  // radius: the interaction radius (kernel support). Throws std::invalid_argument when a
  // periodic axis is shorter than three cells, where the 27-cell stencil would meet itself.
  CellGrid(const Domain& domain, double radius);

  void build(std::span<const Vec3> positions);

  // Particle indices sorted by cell: new_to_old for ParticleStore::reorder.
  std::span<const std::uint32_t> cell_order() const { return sorted_; }

  double radius() const { return radius_; }
  const std::array<int, 3>& cells_per_axis() const { return cells_; }

  // Calls fn(j, r_ij, r2) for every particle j (i itself included) with r2 = |r_ij|^2 < radius^2,
  // where r_ij = x_i - x_j through the nearest periodic image.
  template <class Fn>
  void for_each_neighbour(std::size_t i, std::span<const Vec3> positions, Fn&& fn) const;

  std::size_t bytes() const;

 private:
  int cell_coordinate(double x, int axis) const;
  std::size_t flat(int cx, int cy, int cz) const {
    return (static_cast<std::size_t>(cz) * cells_[1] + cy) * cells_[0] + cx;
  }

  Domain domain_;
  double radius_;
  std::array<int, 3> cells_{1, 1, 1};
  Vec3 cell_size_;
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> sorted_;
};

template <class Fn>
void CellGrid::for_each_neighbour(std::size_t i, std::span<const Vec3> positions, Fn&& fn) const {
  const Vec3& xi = positions[i];
  const double radius2 = radius_ * radius_;
  const Vec3 period = domain_.length();
  int home[3];
  for (int axis = 0; axis < 3; ++axis)
    home[axis] = cell_coordinate(xi[axis], axis);
  const int reach_z = domain_.dimensions == 3 ? 1 : 0;
  for (int dz = -reach_z; dz <= reach_z; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int offset[3] = {dx, dy, dz};
        int c[3];
        Vec3 shift = Vec3::Zero();
        bool inside = true;
        for (int axis = 0; axis < 3 && inside; ++axis) {
          c[axis] = home[axis] + offset[axis];
          if (c[axis] < 0 || c[axis] >= cells_[axis]) {
            if (!domain_.periodic[axis] || cells_[axis] == 1) {
              inside = false;
            } else if (c[axis] < 0) {
              c[axis] += cells_[axis];
              shift[axis] = period[axis];
            } else {
              c[axis] -= cells_[axis];
              shift[axis] = -period[axis];
            }
          }
        }
        if (!inside)
          continue;
        const std::size_t cell = flat(c[0], c[1], c[2]);
        for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
          const std::uint32_t j = sorted_[k];
          const Vec3 rij = xi - positions[j] + shift;
          const double r2 = rij.squaredNorm();
          if (r2 < radius2) {
            fn(static_cast<std::size_t>(j), rij, r2);
          }
        }
      }
    }
  }
}

}  // namespace partimix
