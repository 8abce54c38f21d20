#pragma once
// A triangle mesh (from STL) as a two-sided shell, a contact surface: a grain touches it at the
// nearest point over all triangles (face, edge or corner; Ericson 2005, section 5.1.5), found
// through the bounding volume hierarchy of triangle_bvh.hpp. One contact per mesh and grain, so
// a grain on an edge between two faces is not pushed twice (and a grain in a concave corner
// feels the nearer face only: docs/dem.md, "Walls").
//
// Both sides are material sides: the normal points from the nearest point to the centre and the
// gap is the distance, never negative, so a grain that has crossed the shell is pushed on
// through (the shell is meant to be thicker than a grain can cross in a step). False when the
// distance exceeds `reach` (or the centre lies farther than `reach` outside the mesh's bounding
// box), and for a centre exactly on the mesh (no normal).
#include <memory>

#include "geometry/stl_reader.hpp"
#include "geometry/surface.hpp"
#include "geometry/triangle_bvh.hpp"

namespace partimix::geometry {

class MeshShellSurface final : public Surface {
 public:
  explicit MeshShellSurface(const TriangleSoup& triangles);
  // Shares the hierarchy of a TriangleMesh (no copy of the triangles); `lower` and `upper`
  // bound its triangles.
  MeshShellSurface(std::shared_ptr<const TriangleBvh> bvh, const Vec3& lower, const Vec3& upper);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  std::shared_ptr<const TriangleBvh> bvh_;
  Vec3 lower_;
  Vec3 upper_;
};

}  // namespace partimix::geometry
