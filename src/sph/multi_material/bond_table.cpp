#include "sph/multi_material/bond_table.hpp"

#include <algorithm>

namespace partimix::sph {
namespace {

// The distance of point x from the segment from a to b.
double distance_from_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - x).norm();
}

}  // namespace

void BondTable::build(const CellGrid& reference_grid, std::span<const Vec3> reference,
                      std::span<const double> reference_h, std::span<const std::uint8_t> flagged,
                      double support) {
  const std::size_t n = reference.size();
  first_.assign(n + 1, 0);
  partner_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    first_[i] = partner_.size();
    if (!flagged[i])
      continue;
    reference_grid.for_each_neighbour(i, reference, [&](std::size_t j, const Vec3&, double r2) {
      const double reach = 0.5 * support * (reference_h[i] + reference_h[j]);
      if (j != i && flagged[j] && r2 < reach * reach)
        partner_.push_back(static_cast<std::uint32_t>(j));
    });
  }
  first_[n] = partner_.size();
  cut_.assign(partner_.size(), 0);
  failed_.assign(n, 0);
}

Bond BondTable::state(std::size_t i, std::size_t j) const {
  for (std::size_t b = first_[i]; b < first_[i + 1]; ++b) {
    if (partner_[b] == j)
      return cut_[b] ? Bond::cut : Bond::intact;
  }
  return Bond::none;
}

bool BondTable::lost_bonds(std::size_t i) const {
  return std::any_of(cut_.begin() + static_cast<std::ptrdiff_t>(first_[i]),
                     cut_.begin() + static_cast<std::ptrdiff_t>(first_[i + 1]),
                     [](std::uint8_t c) { return c != 0; });
}

void BondTable::cut(std::size_t i, std::size_t j) {
  for (std::size_t b = first_[i]; b < first_[i + 1]; ++b) {
    if (partner_[b] == j)
      cut_[b] = 1;
  }
  for (std::size_t b = first_[j]; b < first_[j + 1]; ++b) {
    if (partner_[b] == i)
      cut_[b] = 1;
  }
}

// A bond whose segment passes near X_k has an end within the support of X_k (the segment is
// shorter than the support and k lies within half a spacing of it), so k's partners and theirs
// hold every bond the failure can cut.
void BondTable::fail(std::size_t k, std::span<const Vec3> reference, double radius) {
  failed_[k] = 1;
  for (std::size_t b = first_[k]; b < first_[k + 1]; ++b) {
    const std::size_t i = partner_[b];
    cut(k, i);
    for (std::size_t c = first_[i]; c < first_[i + 1]; ++c) {
      const std::size_t j = partner_[c];
      if (!cut_[c] && j != k &&
          distance_from_segment(reference[k], reference[i], reference[j]) <= radius)
        cut(i, j);
    }
  }
}

}  // namespace partimix::sph
