#pragma once
// Verlet neighbour list with a skin (DESIGN.md, "Data and speed"; docs/performance.md,
// "DualSPHysics' CaseDambreak, side by side"): for each particle i < count, the partners j > i that
// lay within radius + skin at the last build, those below `split` first. The list stays valid until
// some particle has moved half the skin since the build, so it serves several force evaluations,
// and each pair is listed once. Built in two passes of a cell grid (count, then fill) into buffers
// that are reused.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "particles/domain.hpp"

namespace partimix {

class NeighbourList {
 public:
  NeighbourList(const Domain& domain, double radius, double skin);

  // Rebuilds the list when it is invalid, when count, split or the number of particles has
  // changed, or when a particle has moved more than half the skin since the last build.
  void update(std::span<const Vec3> positions, std::size_t count, std::size_t split);
  // The particles were reordered: the next update rebuilds.
  void invalidate() { valid_ = false; }

  // Calls below(j, r_ij, r2) for every partner j < split and beyond(j, r_ij, r2) for every
  // partner j >= split of particle i that now lies within the radius, in increasing j, with
  // r_ij = x_i - x_j through the nearest periodic image.
  template <class Below, class Beyond>
  void for_each_partner(std::size_t i, std::span<const Vec3> positions, Below&& below,
                        Beyond&& beyond) const;

  std::size_t builds() const { return builds_; }

 private:
  void build(std::span<const Vec3> positions);
  bool moved_too_far(std::span<const Vec3> positions) const;
  template <class Fn>
  void visit(std::size_t from, std::size_t to, const Vec3& xi, std::span<const Vec3> positions,
             Fn& fn) const;

  Domain domain_;
  bool periodic_;
  double radius_;
  double skin_;
  CellGrid grid_;  // interaction radius radius + skin
  std::size_t count_ = 0;
  std::size_t split_ = 0;
  bool valid_ = false;
  std::size_t builds_ = 0;
  std::vector<std::size_t> first_;   // partners of i: partners_[first_[i], first_[i + 1])
  std::vector<std::size_t> middle_;  // partners of i below split: [first_[i], middle_[i])
  std::vector<std::uint32_t> partners_;
  std::vector<Vec3> built_at_;
};

template <class Fn>
void NeighbourList::visit(std::size_t from, std::size_t to, const Vec3& xi,
                          std::span<const Vec3> positions, Fn& fn) const {
  const double radius2 = radius_ * radius_;
  for (std::size_t k = from; k < to; ++k) {
    const std::uint32_t j = partners_[k];
    const Vec3 rij = periodic_ ? domain_.displacement(xi, positions[j]) : Vec3(xi - positions[j]);
    const double r2 = rij.squaredNorm();
    if (r2 < radius2)
      fn(static_cast<std::size_t>(j), rij, r2);
  }
}

template <class Below, class Beyond>
void NeighbourList::for_each_partner(std::size_t i, std::span<const Vec3> positions, Below&& below,
                                     Beyond&& beyond) const {
  const Vec3& xi = positions[i];
  visit(first_[i], middle_[i], xi, positions, below);
  visit(middle_[i], first_[i + 1], xi, positions, beyond);
}

}  // namespace partimix
