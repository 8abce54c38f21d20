#include "particles/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace partimix {

CellGrid::CellGrid(const Domain& domain, double radius) : domain_(domain), radius_(radius) {
  if (!(radius > 0.0)) {
    throw std::invalid_argument("cell grid: interaction radius must be positive");
  }
  const Vec3 length = domain.length();
  cell_size_ = length;
  periodic_length_ = length;
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    cells_[axis] = std::max(1, static_cast<int>(std::floor(length[axis] / radius)));
    cell_size_[axis] = length[axis] / cells_[axis];
    if (domain.periodic[axis] && cells_[axis] < 3) {
      throw std::invalid_argument("periodic axis " + std::to_string(axis) +
                                  " must be at least three interaction radii long");
    }
  }
  cell_start_.assign(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2] + 1, 0);
}

int CellGrid::cell_coordinate(double x, int axis) const {
  if (cells_[axis] == 1)
    return 0;
  const int c = static_cast<int>(std::floor((x - domain_.lo[axis]) / cell_size_[axis]));
  return std::clamp(c, 0, cells_[axis] - 1);
}

void CellGrid::build(std::span<const Vec3> positions) {
  const std::size_t n = positions.size();
  cell_of_.resize(n);
  sorted_.resize(n);
  std::fill(cell_start_.begin(), cell_start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = positions[i];
    const auto cell = static_cast<std::uint32_t>(
        flat(cell_coordinate(x[0], 0), cell_coordinate(x[1], 1), cell_coordinate(x[2], 2)));
    cell_of_[i] = cell;
    ++cell_start_[cell + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) {
    cell_start_[c] += cell_start_[c - 1];
  }
  for (std::size_t i = 0; i < n; ++i) {
    sorted_[cell_start_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (std::size_t c = cell_start_.size() - 1; c > 0; --c) {
    cell_start_[c] = cell_start_[c - 1];
  }
  cell_start_[0] = 0;
}

std::size_t CellGrid::bytes() const {
  return (cell_of_.capacity() + cell_start_.capacity() + sorted_.capacity()) *
         sizeof(std::uint32_t);
}

}  // namespace partimix
