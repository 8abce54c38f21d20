#pragma once
// The history of each particle's wall contacts (docs/dem.md, "Tangential force"): the tangential
// and rolling springs of every contact, kept per particle in a fixed number of slots so that a
// step does not allocate (the pairs of grains keep theirs in the PairList). A contact is known
// by its partner: a particle id (>= 0) or a face of a wall, -(1 + wall + 2^32 face) (face 0 is
// -(wall index + 1), what a wall was before its faces had contacts of their own, so that older
// checkpoints keep their meaning; docs/dem.md, "Walls of several faces").
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/state_archive.hpp"
#include "core/vec.hpp"

namespace partimix::dem {

struct ContactSlot {
  std::int64_t partner = 0;
  Vec3 spring = Vec3::Zero();          // xi [m]
  Vec3 rolling_spring = Vec3::Zero();  // M_r^k of the elastic-plastic model [N m]
};

class ContactHistory {
 public:
  static constexpr int kMaxCapacity = 64;  // slots per particle; a bit each in a 64-bit mask

  // Throws std::invalid_argument unless 1 <= capacity <= kMaxCapacity.
  ContactHistory(std::size_t particles, int capacity);

  // wall < 2^32, 0 <= face < 2^31.
  static std::int64_t wall_partner(std::size_t wall, int face = 0) {
    return -static_cast<std::int64_t>(wall) - 1 - (static_cast<std::int64_t>(face) << 32);
  }
  // The wall of a wall partner.
  static std::size_t wall_of(std::int64_t partner) {
    return static_cast<std::size_t>((-(partner + 1)) & 0xFFFFFFFF);
  }

  int capacity() const { return capacity_; }
  int count(std::size_t i) const { return counts_[i]; }

  // The slot of i's contact with `partner`, a new zeroed one when there is none; -1 when i's
  // slots are full.
  int find_or_add(std::size_t i, std::int64_t partner);
  // The slot of i's contact with `partner`; -1 when there is none.
  int find(std::size_t i, std::int64_t partner) const;
  ContactSlot& slot(std::size_t i, int k) { return slots_[i * capacity_ + k]; }
  const ContactSlot& slot(std::size_t i, int k) const { return slots_[i * capacity_ + k]; }

  // Keeps the slots k of i with bit k of `touched` set (the contacts of this step), in order.
  void retain(std::size_t i, std::uint64_t touched);

  // Moves the slots with their particles: new particle k is old particle new_to_old[k]. Reuses
  // a scratch buffer, so it does not allocate once that has grown.
  void reorder(std::span<const std::uint32_t> new_to_old);

  std::size_t bytes() const;

  // The live contacts (counts, partners and springs) for a checkpoint, under `prefix`. restore()
  // throws StateError when they do not fit this history (another particle count, a count above
  // the capacity).
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  int capacity_;
  std::vector<ContactSlot> slots_;
  std::vector<std::uint8_t> counts_;
  std::vector<ContactSlot> scratch_slots_;
  std::vector<std::uint8_t> scratch_counts_;
};

}  // namespace partimix::dem
