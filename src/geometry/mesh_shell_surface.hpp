#pragma once
// A triangle mesh (from STL) as a two-sided shell, a contact surface, through the bounding volume
// hierarchy of triangle_bvh.hpp. nearest(): the nearest point over all triangles (face, edge or
// corner; Ericson 2005, section 5.1.5). contacts(): one contact per flat part a sphere touches
// (docs/dem.md, "Walls of several faces"): the triangles are grouped into flat parts (joined
// across edges whose triangles' normals are parallel within 1e-9, the edge's corners equal bit for
// bit); the nearest point of each part within reach, less those that lie on a deeper part (on an
// edge or corner bordering it, or within 1e-9 of the mesh's size of its nearest triangle), so
// that a sphere on a flat or convex part gets one contact and a sphere in a concave corner one
// per face. At most kCandidates parts within reach are looked at (the nearest).
//
// Both sides are material sides: the normal points from the nearest point to the centre and the
// gap is the distance, never negative, so a grain that has crossed the shell is pushed on
// through (the shell is meant to be thicker than a grain can cross in a step). False when the
// distance exceeds `reach` (or the centre lies farther than `reach` outside the mesh's bounding
// box), and for a centre exactly on the mesh (no normal).
//
// Faces: face 2 t + s is triangle t of the hierarchy's order seen from the side of its normal
// (s = 0) or from behind (s = 1); contacts() and faces_near() give the side of the centre.
// nearest_on_face() (for grains that are not spheres) keeps that side. Over the triangle: the
// side's normal and the signed height (negative for a point behind). Beyond an edge or corner,
// by how the surface bends there seen from that side (the neighbour across each edge, found by
// equal corners): past a flat edge the point belongs to the neighbour, and the answer is the
// neighbour's (out.face says which face answered); past concave edges only, the triangle's
// plane goes on (as a box container's face past its closed edges); past a convex or free edge,
// the normal points from the edge or corner to the point, turned over (gap -distance) for a
// point behind the plane. shadowed(): a point of the same triangle, or of a deeper one. ridge():
// a point on a convex edge of its triangle (within the tolerance of "on"), the neighbour's normal
// turned away from the triangle; or at a corner whose edges are all convex or flat, its distinct
// normals in order around it (at most Ridge::kMaxFaces). ridges_near(): the convex edges of the
// face's flat part, and its convex corners of three or more normals, within reach. A face's side
// of its flat part (part_side) is what convex_neighbours() compares.
#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/stl_reader.hpp"
#include "geometry/surface.hpp"
#include "geometry/triangle_bvh.hpp"

namespace partimix::geometry {

class MeshShellSurface final : public Surface {
 public:
  static constexpr int kCandidates = 64;
  static constexpr int kWalk = 64;  // triangles a point walks over a flat part

  explicit MeshShellSurface(const TriangleSoup& triangles);
  // Shares the hierarchy of a TriangleMesh (no copy of the triangles); `lower` and `upper`
  // bound its triangles.
  MeshShellSurface(std::shared_ptr<const TriangleBvh> bvh, const Vec3& lower, const Vec3& upper);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;
  int contacts(const Vec3& centre, double reach, std::span<SurfacePoint> out) const override;
  int faces_near(const Vec3& centre, double reach, std::span<int> out) const override;
  bool nearest_on_face(int face, const Vec3& point, double reach, SurfacePoint& out) const override;
  bool shadowed(const SurfacePoint& candidate, const SurfacePoint& deeper) const override;
  bool ridge(const SurfacePoint& at, Ridge& out) const override;
  int ridges_near(int face, const Vec3& centre, double reach, std::span<Ridge> out) const override;
  bool convex_neighbours(int face_a, int face_b) const override;
  int max_contacts() const override { return 6; }

 private:
  enum class Bend : std::uint8_t { kFree, kFlat, kConcave, kConvex };
  // Two triangles whose unit normals' cross product is below this are flat across their edge.
  static constexpr double kFlat = 1e-9;

  void find_neighbours();
  void find_flat_parts();
  bool near_box(const Vec3& centre, double reach) const;
  // How the surface bends across edge k of triangle `slot`, seen from the side of `side_normal`.
  Bend bend(std::uint32_t slot, int k, const Vec3& side_normal) const;
  int flat_neighbour(int face, const Vec3& point) const;
  // nearest_on_face() beyond the triangle, at its edge or corner `closest`.
  SurfacePoint beyond_triangle(int face, const Vec3& point, const ClosestPoint& closest) const;
  bool behind_concave_neighbour(std::uint32_t slot, int k, const Vec3& point) const;
  struct PartCorner {
    bool concave = true;
    bool behind = false;
  };
  PartCorner part_corner(std::uint32_t slot, int corner, const Vec3& side_normal,
                         const Vec3& point) const;
  // The face of triangle `slot` on the side of `x`.
  int face_towards(std::uint32_t slot, const Vec3& x) const;
  SurfacePoint on_face(int face, const Vec3& point, const ClosestPoint& closest) const;
  bool normal_across(std::uint32_t from, int k, const Vec3& from_normal, Vec3& out) const;
  bool convex_corner(std::uint32_t slot, int corner, Ridge& out) const;
  int seen_side(std::uint32_t slot, const Vec3& normal) const;
  void find_convex_neighbours();
  int part_side(int face) const;
  int face_on_side(std::uint32_t slot, int side) const;

  std::shared_ptr<const TriangleBvh> bvh_;
  Vec3 lower_;
  Vec3 upper_;
  double on_tolerance_ = 0.0;                            // a point this near a triangle lies on it
  std::vector<std::array<std::int32_t, 3>> neighbours_;  // by slot and edge; -1: none
  std::vector<std::int32_t> parts_;                      // the flat part of each slot
  std::vector<std::pair<int, int>> convex_pairs_;  // part sides meeting at a convex edge, sorted
};

}  // namespace partimix::geometry
