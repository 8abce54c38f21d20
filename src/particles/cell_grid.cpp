#include "particles/cell_grid.hpp"

#include <algorithm>
#include <bit>
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
// And at most this many per particle (but kFewestCells), the count rounded up to a power of two:
// a build passes over every cell three times, so a few fine grains in a large domain (1,550 grains
// of 1 mm in a truck drum had the 2^24 cells of 0.6 mm) get larger cells instead. Dense particles
// (SPH, packed grains: a few cells per particle at radius / kReach) are not affected. The bound
// depends on the count alone, so that a run resumed from a checkpoint lays the cells out as the
// run that went through did, and changes only when the count crosses a power of two.
constexpr double kCellsPerParticle = 16.0;
constexpr double kFewestCells = 4096.0;

double most_cells(std::size_t particles) {
  const double rounded = static_cast<double>(std::bit_ceil(std::max<std::size_t>(particles, 1)));
  return std::clamp(kCellsPerParticle * rounded, kFewestCells, kMaxCells);
}

constexpr const char* kAxisNames[] = {"x", "y", "z"};

}  // namespace

CellGrid::CellGrid(const Domain& domain, double radius) : domain_(domain), radius_(radius) {
  if (!(radius > 0.0)) {
    throw std::invalid_argument("cell grid: interaction radius must be positive");
  }
  const Vec3 length = domain.length();
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    wanted_[axis] = std::max(1.0, std::floor(kReach * length[axis] / radius));
    if (domain.periodic[axis] && length[axis] < 3.0 * radius) {
      throw InputError(
          InputLocation{"", 0, 0, "domain.periodic"},
          fmt::format("the periodic axis {} is {:.6g} m long; it must be at least three "
                      "interaction radii, 3 x {:.6g} m = {:.6g} m",
                      kAxisNames[axis], length[axis], radius, 3.0 * radius));
    }
  }
  periodic_length_ = length;
  lay_out(most_cells(0));
}

// Cells radius / kReach wide, or wider where that would make more than `most`.
void CellGrid::lay_out(double most) {
  most_ = most;
  const double total = wanted_[0] * wanted_[1] * wanted_[2];
  const double shrink = total > most ? std::pow(most / total, 1.0 / domain_.dimensions) : 1.0;
  const Vec3 length = domain_.length();
  cell_size_ = length;
  for (int axis = 0; axis < domain_.dimensions; ++axis) {
    const double floor_cells = domain_.periodic[axis] ? 2.0 * kReach + 1.0 : 1.0;
    cells_[axis] = static_cast<int>(std::max(floor_cells, std::floor(wanted_[axis] * shrink)));
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

// The cells are laid out again when the particle count has changed the bound on them.
void CellGrid::build(std::span<const Vec3> positions) {
  const std::size_t n = positions.size();
  const double most = most_cells(n);
  if (most != most_)
    lay_out(most);
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
