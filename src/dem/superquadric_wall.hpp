#pragma once
// The contacts of a superquadric grain with a wall surface (docs/dem.md, "Walls and
// superquadrics"): per face, the grain's deepest point into that face, found by iterating between
// the grain's support point against the face's normal and the face's nearest point to it, until
// the normal stops turning (at once for a plane); over the faces near the grain, those contacts
// less the ones a deeper face shadows, as for spheres (docs/dem.md, "Walls of several faces").
#include <span>

#include "dem/superquadric.hpp"
#include "geometry/surface.hpp"

namespace partimix::dem {

// Plain members without initialisers: the buffers of a wall's face contacts are built per grain
// and wall every step; superquadric_face_contact sets every member.
struct WallContact {
  bool touching;
  bool converged;               // false: the normal still turned after the last iteration
  Vec3 normal;                  // from the wall to the grain
  double overlap;               // > 0 when touching
  Vec3 point;                   // halfway between the deepest point and the surface
  geometry::SurfacePoint wall;  // the face's point nearest the deepest point, its face and gap
};

// The grain of `shape` centred at `centre` and turned by `rotation` (body to the surface's
// frame) against face `face` of `surface` alone, a face within the grain's bounding radius of
// its centre.
WallContact superquadric_face_contact(const Superquadric& shape, const Vec3& centre,
                                      const Mat3& rotation, const geometry::Surface& surface,
                                      int face = 0);

// The most faces of one wall looked at for one grain.
inline constexpr int kFaceCandidates = 64;

// The same grain against every face of `surface` within its bounding radius (at most
// kFaceCandidates, the nearest): the touching contacts, deepest first, at most out.size();
// returns their number and adds the faces whose iteration did not converge to `failures`.
// No allocation.
int superquadric_wall_contacts(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                               const geometry::Surface& surface, std::span<WallContact> out,
                               int& failures);

}  // namespace partimix::dem
