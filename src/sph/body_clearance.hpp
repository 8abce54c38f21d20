#pragma once
// Where the fluid's lattice points may lie beside solid bodies (docs/geometry-meshes.md, "Solid
// walls"): outside every body and at least one spacing from each of its particles. On the
// fluid's own lattice that keeps every point outside, so that fluid and body particles tile the
// lattice and the body's surface lies between them, curved or not; a body laid on a lattice of
// another phase keeps the fluid points that would come closer than a spacing to its particles
// away. (A clearance of half a spacing from the surface left a band up to half a spacing wide
// empty along a curved body: the loads on a turning cylinder came out 9% low.) The body
// particles sit in a hash of cells a spacing wide: CellGrid lists the neighbours of its own
// particles, and these queries are of other points.
#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/vec.hpp"
#include "geometry/shape.hpp"
#include "particles/domain.hpp"

namespace partimix::sph {

class BodyClearance {
 public:
  BodyClearance(const Domain& domain, double spacing);

  // A solid body: its shape and its particles.
  void add_body(const geometry::Shape& shape, std::span<const Vec3> particles);

  // Whether a fluid point at x is inside a body or closer than a spacing to a body particle.
  bool blocks(const Vec3& x) const;

 private:
  std::array<std::int64_t, 3> cell_of(const Vec3& x) const;
  std::int64_t key(std::array<std::int64_t, 3> cell) const;
  bool near_box(const geometry::Shape& shape, const Vec3& x) const;
  bool near_particle(const Vec3& x) const;

  Domain domain_;
  double spacing_;
  std::array<std::int64_t, 3> periodic_cells_{0, 0, 0};  // cells along each periodic axis
  std::vector<const geometry::Shape*> shapes_;
  std::vector<Vec3> particles_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace partimix::sph
