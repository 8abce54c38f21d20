#pragma once
// The bonds of total Lagrangian solids and the cracks that cut them (docs/multi-material-sph.md,
// "Total Lagrangian solids", cracks). Each particle of such a solid is bonded to the others
// within the kernel's support of their mean reference smoothing length, in the reference
// configuration X. A fully damaged particle k fails: its bonds are cut, and so is every bond i-j
// whose reference segment X_i X_j passes within `radius` (half k's spacing) of X_k, so that a
// path of failed particles cuts the bonds across it, however far the kernel reaches. Which bonds
// are cut depends only on which particles have failed, not on the order they failed in.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"

namespace partimix::sph {

enum class Bond { none, intact, cut };

class BondTable {
 public:
  // Bonds each flagged particle to the flagged particles j with |X_ij| < support (h_i + h_j) / 2,
  // in the order the reference grid (built on `reference`) visits them; none are cut.
  void build(const CellGrid& reference_grid, std::span<const Vec3> reference,
             std::span<const double> reference_h, std::span<const std::uint8_t> flagged,
             double support);
  // Particle k fails: its bonds, and those whose reference segment passes within radius of X_k,
  // are cut.
  void fail(std::size_t k, std::span<const Vec3> reference, double radius);

  bool failed(std::size_t i) const { return failed_[i] != 0; }
  // Whether any of i's bonds is cut.
  bool lost_bonds(std::size_t i) const;
  // Whether i and j were bonded at the start, and if so whether the bond is cut.
  Bond state(std::size_t i, std::size_t j) const;
  // Calls fn(j) for every particle j whose bond to i is intact.
  template <class Fn>
  void for_each_intact(std::size_t i, Fn&& fn) const {
    for (std::size_t b = first_[i]; b < first_[i + 1]; ++b) {
      if (!cut_[b])
        fn(static_cast<std::size_t>(partner_[b]));
    }
  }

 private:
  void cut(std::size_t i, std::size_t j);

  std::vector<std::size_t> first_;  // particle i's bonds are [first_[i], first_[i + 1])
  std::vector<std::uint32_t> partner_;
  std::vector<std::uint8_t> cut_;
  std::vector<std::uint8_t> failed_;
};

}  // namespace partimix::sph
