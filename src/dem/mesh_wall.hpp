#pragma once
// A triangle mesh (from STL) as a two-sided shell: a sphere touches it at the nearest point over
// all triangles (face, edge or corner; Ericson 2005, section 5.1.5), found through the bounding
// volume hierarchy of src/geometry. One contact per mesh and sphere, so a sphere on an edge
// between two faces is not pushed twice (and a sphere in a concave corner feels the nearer face
// only: docs/dem.md, "Walls").
#include "dem/wall_surface.hpp"
#include "geometry/stl_reader.hpp"
#include "geometry/triangle_bvh.hpp"

namespace partimix::dem {

class MeshWall final : public WallSurface {
 public:
  explicit MeshWall(const geometry::TriangleSoup& triangles);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  geometry::TriangleBvh bvh_;
  Vec3 lower_;
  Vec3 upper_;
};

}  // namespace partimix::dem
