#pragma once
// The contact of a superquadric grain with a wall surface (docs/dem.md, "Walls and
// superquadrics"): the grain's deepest point into the wall, found by iterating between the
// grain's support point against the wall's normal and the wall's nearest point to it, until the
// normal stops turning (at once for a plane).
#include "dem/superquadric.hpp"
#include "geometry/surface.hpp"

namespace partimix::dem {

struct WallContact {
  bool touching = false;
  bool converged = true;        // false: the normal still turned after the last iteration
  Vec3 normal = Vec3::UnitZ();  // from the wall to the grain
  double overlap = 0.0;         // > 0 when touching
  Vec3 point = Vec3::Zero();    // halfway between the deepest point and the surface
};

// The grain of `shape` centred at `centre` and turned by `rotation` (body to the surface's
// frame) against `surface`.
WallContact superquadric_wall_contact(const Superquadric& shape, const Vec3& centre,
                                      const Mat3& rotation, const geometry::Surface& surface);

}  // namespace partimix::dem
