#pragma once
// Whether a damaged shell has ruptured (docs/multi-material-sph.md, "The scheme", droplet
// measurements): a path of fully damaged particles, each within `link` of the next, joining a
// particle of the shell's inner surface to one of its outer surface. Found by a breadth-first
// search from the damaged inner-surface particles over the damaged ones.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"

namespace partimix::analysis {

enum class ShellSurface : std::int8_t { none = 0, inner = 1, outer = 2 };

class ShellRupture {
 public:
  // damage >= `failed` counts as fully damaged.
  explicit ShellRupture(double link, double failed = 1.0) : link_(link), failed_(failed) {}

  // True when a path of fully damaged shell particles joins the two surfaces. The particles
  // are the shell's alone; O(n^2) pairs, meant for a shell of a few thousand particles sampled
  // now and then.
  bool ruptured(std::span<const Vec3> position, std::span<const double> damage,
                std::span<const ShellSurface> surface);

 private:
  double link_;
  double failed_;
  std::vector<std::uint8_t> reached_;  // kept between calls
  std::vector<std::size_t> queue_;
};

}  // namespace partimix::analysis
