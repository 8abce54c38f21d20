#pragma once
// The six sides of a grid fluid's box (docs/cfd.md, "Walls: blocked cells"): each a wall that
// moves in its own plane at `velocity` (a lid), no-slip or slip; a periodic axis has none.
// Sides are numbered 2 axis + (0 below, 1 above).
#include <array>

#include "core/vec.hpp"

namespace partimix::cfd {

struct BoxSide {
  bool slip = false;
  Vec3 velocity = Vec3::Zero();
};

using BoxSides = std::array<BoxSide, 6>;

inline const BoxSide& box_side(const BoxSides& sides, int axis, int side) {
  return sides[static_cast<std::size_t>(2 * axis + (side > 0 ? 1 : 0))];
}

}  // namespace partimix::cfd
