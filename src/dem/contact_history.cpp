#include "dem/contact_history.hpp"

#include <algorithm>
#include <stdexcept>

namespace partimix::dem {

ContactHistory::ContactHistory(std::size_t particles, int capacity) : capacity_(capacity) {
  if (capacity < 1 || capacity > kMaxCapacity)
    throw std::invalid_argument("ContactHistory: capacity must lie in [1, 64]");
  slots_.resize(particles * capacity_);
  counts_.assign(particles, 0);
}

int ContactHistory::find_or_add(std::size_t i, std::int64_t partner) {
  ContactSlot* first = &slots_[i * capacity_];
  const int count = counts_[i];
  for (int k = 0; k < count; ++k) {
    if (first[k].partner == partner)
      return k;
  }
  if (count == capacity_)
    return -1;
  first[count] = ContactSlot{partner, Vec3::Zero(), Vec3::Zero()};
  counts_[i] = static_cast<std::uint8_t>(count + 1);
  return count;
}

void ContactHistory::retain(std::size_t i, std::uint64_t touched) {
  ContactSlot* first = &slots_[i * capacity_];
  int kept = 0;
  for (int k = 0; k < counts_[i]; ++k) {
    if ((touched >> k) & 1U)
      first[kept++] = first[k];
  }
  counts_[i] = static_cast<std::uint8_t>(kept);
}

void ContactHistory::reorder(std::span<const std::uint32_t> new_to_old) {
  scratch_slots_.resize(slots_.size());
  scratch_counts_.resize(counts_.size());
  for (std::size_t k = 0; k < new_to_old.size(); ++k) {
    const std::size_t old = new_to_old[k];
    scratch_counts_[k] = counts_[old];
    std::copy_n(&slots_[old * capacity_], counts_[old], &scratch_slots_[k * capacity_]);
  }
  slots_.swap(scratch_slots_);
  counts_.swap(scratch_counts_);
}

std::size_t ContactHistory::bytes() const {
  return (slots_.capacity() + scratch_slots_.capacity()) * sizeof(ContactSlot) +
         counts_.capacity() + scratch_counts_.capacity();
}

}  // namespace partimix::dem
