#pragma once
// The one check every triangle mesh goes through after it is read (docs/geometry-meshes.md),
// whichever method uses it: corners finite, and triangles without area dropped. A mesh with no
// triangle left is refused, for SPH (a shape) and DEM (a contact surface) alike.
#include "geometry/stl_reader.hpp"

namespace partimix::geometry {

// The triangles of `triangles` moved by `offset`, less those without area (two edges parallel
// to within 1e-12 of the longest edge squared: a repeated corner, or three corners on a line).
// Throws InputError (without a location: the caller names the key) when a corner is not finite
// or no triangle has an area.
TriangleSoup checked_triangles(TriangleSoup triangles, const Vec3& offset);

}  // namespace partimix::geometry
