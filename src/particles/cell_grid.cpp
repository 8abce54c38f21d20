#include "particles/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix {

namespace {

// At most this many cells, whatever the domain's size: a large domain gets larger cells (still
// at least radius / kReach wide), so the grid's memory is bounded (4 bytes per cell).
constexpr double kMaxCells = 1 << 24;

constexpr const char* kAxisNames[] = {"x", "y", "z"};

}  // namespace

CellGrid::CellGrid(const Domain& domain, double radius) : domain_(domain), radius_(radius) {
  if (!(radius > 0.0)) {
    throw std::invalid_argument("cell grid: interaction radius must be positive");
  }
  const Vec3 length = domain.length();
  std::array<double, 3> wanted{1.0, 1.0, 1.0};
  double total = 1.0;
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    wanted[axis] = std::max(1.0, std::floor(kReach * length[axis] / radius));
    total *= wanted[axis];
    if (domain.periodic[axis] && length[axis] < 3.0 * radius) {
      throw InputError(
          InputLocation{"", 0, 0, "domain.periodic"},
          fmt::format("the periodic axis {} is {:.6g} m long; it must be at least three "
                      "interaction radii, 3 x {:.6g} m = {:.6g} m",
                      kAxisNames[axis], length[axis], radius, 3.0 * radius));
    }
  }
  const double shrink =
      total > kMaxCells ? std::pow(kMaxCells / total, 1.0 / domain.dimensions) : 1.0;
  cell_size_ = length;
  periodic_length_ = length;
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    const double floor_cells = domain.periodic[axis] ? 2.0 * kReach + 1.0 : 1.0;
    cells_[axis] = static_cast<int>(std::max(floor_cells, std::floor(wanted[axis] * shrink)));
    cell_size_[axis] = length[axis] / cells_[axis];
  }
  cell_start_.assign(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2] + 1, 0);
}

// NaN and infinite coordinates land in an edge cell; the health check reports them.
int CellGrid::cell_coordinate(double x, int axis) const {
  if (cells_[axis] == 1)
    return 0;
  const double c = std::floor((x - domain_.lo[axis]) / cell_size_[axis]);
  if (!(c > 0.0))
    return 0;
  return c >= cells_[axis] - 1 ? cells_[axis] - 1 : static_cast<int>(c);
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
