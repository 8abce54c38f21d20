#include "sph/body_clearance.hpp"

#include <cmath>

namespace partimix::sph {
namespace {

// Points exactly a spacing apart (two points of one lattice, up to round-off) are clear.
constexpr double kClear = 1.0 - 1e-9;

bool within_box(const geometry::Shape& shape, const Vec3& x) {
  return (x.array() >= shape.lower().array()).all() && (x.array() <= shape.upper().array()).all();
}

}  // namespace

BodyClearance::BodyClearance(const Domain& domain, double spacing)
    : domain_(domain), spacing_(spacing) {
  for (int axis = 0; axis < 3; ++axis) {
    if (domain.periodic[axis]) {
      const double cells = std::floor(domain.length()[axis] / spacing);
      periodic_cells_[axis] = std::max<std::int64_t>(1, static_cast<std::int64_t>(cells));
    }
  }
}

// Cells at least a spacing wide: along a periodic axis a whole number of them spans the period.
std::array<std::int64_t, 3> BodyClearance::cell_of(const Vec3& x) const {
  std::array<std::int64_t, 3> cell{0, 0, 0};
  for (int axis = 0; axis < domain_.dimensions; ++axis) {
    const std::int64_t n = periodic_cells_[axis];
    const double size = n > 0 ? domain_.length()[axis] / static_cast<double>(n) : spacing_;
    cell[axis] = static_cast<std::int64_t>(std::floor((x[axis] - domain_.lo[axis]) / size));
    if (n > 0)
      cell[axis] = ((cell[axis] % n) + n) % n;
  }
  return cell;
}

// Cells that share a key share a bucket: more candidates to measure, never a missed one.
std::int64_t BodyClearance::key(std::array<std::int64_t, 3> cell) const {
  for (int axis = 0; axis < 3; ++axis) {
    const std::int64_t n = periodic_cells_[axis];
    if (n > 0)
      cell[axis] = ((cell[axis] % n) + n) % n;
  }
  return (cell[0] * 73856093) ^ (cell[1] * 19349663) ^ (cell[2] * 83492791);
}

void BodyClearance::add_body(const geometry::Shape& shape, std::span<const Vec3> particles) {
  shapes_.push_back(&shape);
  for (const Vec3& x : particles) {
    cells_[key(cell_of(x))].push_back(static_cast<std::uint32_t>(particles_.size()));
    particles_.push_back(x);
  }
}

bool BodyClearance::near_particle(const Vec3& x) const {
  const std::array<std::int64_t, 3> centre = cell_of(x);
  const int reach_z = domain_.dimensions == 3 ? 1 : 0;
  const double limit = kClear * spacing_;
  for (int dz = -reach_z; dz <= reach_z; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const auto found = cells_.find(key({centre[0] + dx, centre[1] + dy, centre[2] + dz}));
        if (found == cells_.end())
          continue;
        for (const std::uint32_t k : found->second) {
          if (domain_.displacement(x, particles_[k]).squaredNorm() < limit * limit)
            return true;
        }
      }
    }
  }
  return false;
}

bool BodyClearance::blocks(const Vec3& x) const {
  for (const geometry::Shape* shape : shapes_) {
    if (within_box(*shape, x) && shape->signed_distance(x) < 0.0)
      return true;
  }
  return near_particle(x);
}

}  // namespace partimix::sph
