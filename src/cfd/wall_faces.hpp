#pragma once
// The faces of a grid fluid's blocked cells inside the box, and the velocity of the wall there
// (docs/cfd.md, "Moving walls and the rotating frame"): a face takes its wall's velocity at its
// centre, normal component included, when the wall moves along its own surface. The shear rate
// of a non-Newtonian fluid next to such a wall reads the wall's tangential components here.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec.hpp"

namespace partimix::cfd {

struct WallFaces {
  // Per axis: each wall face with a blocked cell beside it.
  std::array<std::vector<std::pair<std::size_t, std::size_t>>, 3> faces;
  // Per axis and face: its slot in `faces` and `velocity`, -1 for a face that is not a wall's.
  std::array<std::vector<std::int32_t>, 3> slot;
  // Per axis, by slot: the wall's velocity at the face's centre (zero for a wall at rest).
  std::array<std::vector<Vec3>, 3> velocity;

  // The wall's velocity at face `face` of component `axis`; zero where there is no wall face.
  Vec3 at(int axis, std::size_t face) const {
    const std::int32_t s = slot[axis][face];
    return s < 0 ? Vec3::Zero() : velocity[axis][static_cast<std::size_t>(s)];
  }
};

}  // namespace partimix::cfd
