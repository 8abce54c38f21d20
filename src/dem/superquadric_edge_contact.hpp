#pragma once
// A superquadric grain against the solid behind a convex edge or corner of a wall (docs/dem.md,
// "Walls and superquadrics", Convex edges and corners): the least overlap over the cone of the
// edge's or corner's normals, the separating-axis minimum, so that a convex grain meets the
// convex solid in one contact however many faces meet there.
#include "dem/superquadric.hpp"
#include "dem/superquadric_wall.hpp"
#include "geometry/surface.hpp"

namespace partimix::dem {

// The grain of `shape` centred at `centre` and turned by `rotation` (body to the surface's
// frame) against the solid behind `ridge`'s faces; the contact belongs to the face of the normal
// nearest its own. converged is false when a corner's iteration did not settle.
WallContact edge_contact(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                         const geometry::Ridge& ridge);

}  // namespace partimix::dem
