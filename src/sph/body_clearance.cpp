#include "sph/body_clearance.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::sph {
namespace {

// Points exactly a spacing apart (two points of one lattice, up to round-off) are clear.
constexpr double kClear = 1.0 - 1e-9;
constexpr double kFar = 1e15;

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
    // Clamped so that any position converts: cells beyond share one index (and are measured).
    const double c = std::clamp(std::floor((x[axis] - domain_.lo[axis]) / size), -kFar, kFar);
    cell[axis] = static_cast<std::int64_t>(c);  // key() wraps it along a periodic axis
  }
  return cell;
}

// A cell's index wrapped along the periodic axes (so that cell_of(x) +- 1 finds the other side),
// hashed: cells that share a key share a bucket, more candidates to measure, never a missed one.
std::int64_t BodyClearance::key(std::array<std::int64_t, 3> cell) const {
  for (int axis = 0; axis < 3; ++axis) {
    const std::int64_t n = periodic_cells_[axis];
    if (n > 0)
      cell[axis] = ((cell[axis] % n) + n) % n;
  }
  const auto mix = [](std::int64_t c, std::uint64_t factor) {
    return static_cast<std::uint64_t>(c) * factor;  // unsigned: wraps, never overflows
  };
  return static_cast<std::int64_t>(mix(cell[0], 73856093U) ^ mix(cell[1], 19349663U) ^
                                   mix(cell[2], 83492791U));
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

// Most fluid points lie farther than a spacing from every body's bounding box: no search then.
bool BodyClearance::blocks(const Vec3& x) const {
  bool near_a_body = false;
  for (const geometry::Shape* shape : shapes_) {
    if (within_box(*shape, x) && shape->signed_distance(x) < 0.0)
      return true;
    near_a_body = near_a_body || near_box(*shape, x);
  }
  return near_a_body && near_particle(x);
}

// Within a spacing of the shape's bounding box along every axis that is not periodic (along a
// periodic one, a particle's image may come near from the other side).
bool BodyClearance::near_box(const geometry::Shape& shape, const Vec3& x) const {
  for (int axis = 0; axis < 3; ++axis) {
    const bool outside =
        x[axis] < shape.lower()[axis] - spacing_ || x[axis] > shape.upper()[axis] + spacing_;
    if (outside && !domain_.periodic[axis])
      return false;
  }
  return true;
}

}  // namespace partimix::sph
