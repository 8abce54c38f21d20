#pragma once
// The contact surface of a wall (docs/dem.md, "Walls"): where a grain touches it. A surface
// answers one question, the point of the surface nearest to a grain's centre, in the wall's own
// frame (where the wall is at t = 0; the DEM solver moves centres into that frame with the wall's
// motion). One contact per wall and grain: a grain near an edge between two faces touches the
// nearer face (or the edge) only, so it is never pushed twice.
//
// Convention: every surface has a material side, where the grains belong (inside a container,
// outside a solid body). The normal points from the surface towards that side, so the gap is
// positive for a centre on the material side and negative for a centre that has crossed the
// surface (still in contact, with overlap R - gap). Each surface's header says exactly what it
// returns at its edges, rims and open faces.
#include "core/vec.hpp"

namespace partimix::geometry {

struct SurfacePoint {
  Vec3 point = Vec3::Zero();    // the nearest point of the surface
  Vec3 normal = Vec3::UnitZ();  // unit, from the surface towards the material side
  double gap = 0.0;             // (centre - point) . normal: overlap = R - gap
};

class Surface {
 public:
  virtual ~Surface() = default;
  // The nearest point to `centre`; false when the centre lies farther than `reach` from the
  // surface on its material side (no contact possible), or, for some surfaces, where the
  // nearest point is not defined (said in their headers).
  virtual bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const = 0;
  // True for one smooth face (a plane, a drum shell, a cone's side), which a convex grain meets
  // at one point at most. Surfaces of several faces (boxes, vessels, meshes) give one contact per
  // wall, which a sphere's nearest point handles but a long grain lying in a corner defeats.
  virtual bool single_face() const { return false; }
};

}  // namespace partimix::geometry
