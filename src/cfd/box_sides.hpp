#pragma once
// The six sides of a grid fluid's box (docs/cfd.md, "Walls: blocked cells"; "Inlets and
// outlets"): each a no-slip wall that moves at `velocity` (in its plane: a lid; across it: an
// inlet), a slip wall, or a pressure outlet (p = 0 on the side, the velocity's gradient across
// it zero); a periodic axis has none. Sides are numbered 2 axis + (0 below, 1 above).
#include <array>

#include "core/vec.hpp"

namespace partimix::cfd {

struct BoxSide {
  bool slip = false;
  bool outlet = false;
  Vec3 velocity = Vec3::Zero();
};

using BoxSides = std::array<BoxSide, 6>;

inline const BoxSide& box_side(const BoxSides& sides, int axis, int side) {
  return sides[static_cast<std::size_t>(2 * axis + (side > 0 ? 1 : 0))];
}

}  // namespace partimix::cfd
