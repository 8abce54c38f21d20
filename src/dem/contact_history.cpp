#include "dem/contact_history.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace partimix::dem {

ContactHistory::ContactHistory(std::size_t particles, int capacity) : capacity_(capacity) {
  if (capacity < 1 || capacity > kMaxCapacity)
    throw std::invalid_argument("ContactHistory: capacity must lie in [1, 64]");
  slots_.resize(particles * capacity_);
  counts_.assign(particles, 0);
}

int ContactHistory::find(std::size_t i, std::int64_t partner) const {
  const ContactSlot* first = &slots_[i * capacity_];
  for (int k = 0; k < counts_[i]; ++k) {
    if (first[k].partner == partner)
      return k;
  }
  return -1;
}

int ContactHistory::find_or_add(std::size_t i, std::int64_t partner) {
  const int found = find(i, partner);
  if (found >= 0)
    return found;
  ContactSlot* first = &slots_[i * capacity_];
  const int count = counts_[i];
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

void ContactHistory::save(StateArchive& archive, const std::string& prefix) const {
  std::vector<std::int64_t> counts(counts_.begin(), counts_.end());
  std::vector<std::int64_t> partners;
  std::vector<Vec3> springs;
  std::vector<Vec3> rolling_springs;
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    for (int k = 0; k < counts_[i]; ++k) {
      const ContactSlot& slot = slots_[i * capacity_ + k];
      partners.push_back(slot.partner);
      springs.push_back(slot.spring);
      rolling_springs.push_back(slot.rolling_spring);
    }
  }
  archive.put_integers(prefix + "counts", counts);
  archive.put_integers(prefix + "partners", partners);
  archive.put_vectors(prefix + "springs", springs);
  archive.put_vectors(prefix + "rolling_springs", rolling_springs);
}

void ContactHistory::restore(const StateArchive& archive, const std::string& prefix) {
  const auto counts = archive.integers(prefix + "counts");
  const auto partners = archive.integers(prefix + "partners");
  const std::vector<Vec3> springs = archive.vectors(prefix + "springs");
  const std::vector<Vec3> rolling_springs = archive.vectors(prefix + "rolling_springs");
  if (counts.size() != counts_.size())
    throw StateError(fmt::format("{}counts: {} particles, the case has {}", prefix, counts.size(),
                                 counts_.size()));
  std::size_t next = 0;
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    const auto count = static_cast<std::size_t>(std::clamp<std::int64_t>(counts[i], -1, 65));
    if (counts[i] < 0 || counts[i] > capacity_ || next + count > partners.size() ||
        next + count > springs.size() || next + count > rolling_springs.size())
      throw StateError(fmt::format("{}: the contacts of particle {} do not fit", prefix, i));
    counts_[i] = static_cast<std::uint8_t>(count);
    for (int k = 0; k < counts_[i]; ++k, ++next)
      slots_[i * capacity_ + k] = {partners[next], springs[next], rolling_springs[next]};
  }
}

std::size_t ContactHistory::bytes() const {
  return (slots_.capacity() + scratch_slots_.capacity()) * sizeof(ContactSlot) +
         counts_.capacity() + scratch_counts_.capacity();
}

}  // namespace partimix::dem
