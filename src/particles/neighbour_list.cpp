#include "particles/neighbour_list.hpp"

#include <algorithm>
#include <cstddef>

namespace partimix {

NeighbourList::NeighbourList(const Domain& domain, double radius, double skin)
    : domain_(domain),
      periodic_(domain.periodic[0] || domain.periodic[1] || domain.periodic[2]),
      radius_(radius),
      skin_(skin),
      grid_(domain, radius + skin) {}

void NeighbourList::update(std::span<const Vec3> positions, std::size_t count, std::size_t split) {
  const bool same_layout =
      valid_ && count == count_ && split == split_ && positions.size() == built_at_.size();
  if (same_layout && !moved_too_far(positions))
    return;
  count_ = count;
  split_ = split;
  build(positions);
}

bool NeighbourList::moved_too_far(std::span<const Vec3> positions) const {
  const double limit2 = 0.25 * skin_ * skin_;
  const auto n = static_cast<std::ptrdiff_t>(positions.size());
  bool too_far = false;
#pragma omp parallel for schedule(static) reduction(|| : too_far)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    too_far = too_far || !((positions[i] - built_at_[i]).squaredNorm() <= limit2);
  }
  return too_far;
}

// Pass 1 counts each particle's partners below and beyond split, pass 2 writes them. Each part
// is sorted by index, so that the partners within the radius are visited in the same order
// whenever the list was built: a run resumed from a checkpoint sums its pairs as the
// uninterrupted run did (bitwise; tests/system/kill_and_resume_test.cpp).
void NeighbourList::build(std::span<const Vec3> positions) {
  grid_.build(positions);
  const auto n = static_cast<std::ptrdiff_t>(count_);
  first_.resize(count_ + 1);
  middle_.resize(count_);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::size_t below = 0;
    std::size_t beyond = 0;
    grid_.for_each_neighbour(
        i, positions, [&](std::size_t, const Vec3&, double) { ++below; }, split_, i + 1);
    grid_.for_each_neighbour(
        i, positions, [&](std::size_t, const Vec3&, double) { ++beyond; }, positions.size(),
        std::max(split_, i + 1));
    first_[i + 1] = below + beyond;
    middle_[i] = below;
  }
  first_[0] = 0;
  for (std::size_t i = 0; i < count_; ++i) {
    first_[i + 1] += first_[i];
    middle_[i] += first_[i];
  }
  // Grow with a quarter to spare, so that a list that breathes with the flow does not
  // allocate at every build.
  const std::size_t total = first_[count_];
  if (total > partners_.capacity())
    partners_.reserve(total + total / 4);
  partners_.resize(total);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::size_t next = first_[i];
    auto add = [&](std::size_t j, const Vec3&, double) {
      partners_[next++] = static_cast<std::uint32_t>(j);
    };
    grid_.for_each_neighbour(i, positions, add, split_, i + 1);
    grid_.for_each_neighbour(i, positions, add, positions.size(), std::max(split_, i + 1));
    std::sort(partners_.begin() + first_[i], partners_.begin() + middle_[i]);
    std::sort(partners_.begin() + middle_[i], partners_.begin() + first_[i + 1]);
  }
  built_at_.assign(positions.begin(), positions.end());
  valid_ = true;
  ++builds_;
}

}  // namespace partimix
