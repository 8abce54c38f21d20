#pragma once
// Whether a 2D shell still closes round its centre (docs/multi-material-sph.md, "The scheme",
// droplet measurements): the shell's intact particles (damage below `failed`), joined when within
// `link` of each other, close round the centre when some cycle of joins winds round it. A shell
// that opens by its particles parting, without a path of fully damaged particles, fails this test.
// Found by a breadth-first search that carries each particle's angle about the centre unwrapped
// along the joins: a join whose ends disagree by a whole turn closes a winding cycle.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"

namespace partimix::analysis {

class ShellRing {
 public:
  // damage >= `failed` counts as fully damaged.
  explicit ShellRing(double link, double failed = 1.0) : link_(link), failed_(failed) {}

  // True when a cycle of intact shell particles, each within link of the next, winds round
  // `centre` in the xy plane. The particles are the shell's alone, all farther than link from
  // the centre; O(n^2) pairs, meant for a shell of a few thousand particles sampled now and then.
  bool closes(std::span<const Vec3> position, std::span<const double> damage, const Vec3& centre);

 private:
  bool closes_from(std::size_t seed, std::span<const Vec3> position,
                   std::span<const double> damage);

  double link_;
  double failed_;
  std::vector<double> angle_;      // about the centre, in (-pi, pi]
  std::vector<double> unwrapped_;  // along the search's joins
  std::vector<std::uint8_t> reached_;
  std::vector<std::size_t> queue_;  // all kept between calls
};

}  // namespace partimix::analysis
