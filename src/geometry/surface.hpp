#pragma once
// The contact surface of a wall (docs/dem.md, "Walls"): where a grain touches it. A surface
// answers, in the wall's own frame (where the wall is at t = 0; the DEM solver moves centres into
// that frame with the wall's motion), the point of the surface nearest to a grain's centre, and,
// for a surface of several faces (a box, a vessel, a mesh), one contact per face that a sphere
// touches (docs/dem.md, "Walls of several faces"): a sphere in a concave corner touches both
// faces, a sphere on a flat or convex part of the surface one point only.
//
// Convention: every surface has a material side, where the grains belong (inside a container,
// outside a solid body). The normal points from the surface towards that side, so the gap is
// positive for a centre on the material side and negative for a centre that has crossed the
// surface (still in contact, with overlap R - gap). Each surface's header says exactly what it
// returns at its edges, rims and open faces.
#include <array>
#include <span>

#include "core/vec.hpp"

namespace partimix::geometry {

struct SurfacePoint {
  Vec3 point = Vec3::Zero();    // the nearest point of the surface (or of one face)
  Vec3 normal = Vec3::UnitZ();  // unit, from the surface towards the material side
  double gap = 0.0;             // (centre - point) . normal: overlap = R - gap
  int face = 0;                 // the face it lies on, >= 0 (stable for the surface's life)
};

// Where faces of a surface meet in a convex way seen from its material side: an edge, the segment
// [start, end] between two faces, or a corner (start = end) of two or more faces (two: a corner
// along a straight edge). `normals` holds the faces' unit normals towards the material side, in
// their order around the corner, each with a face that holds the edge or corner. Near it the wall
// is the solid behind all these faces (docs/dem.md, "Walls and superquadrics", Convex edges).
struct Ridge {
  static constexpr int kMaxFaces = 8;
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  std::array<Vec3, kMaxFaces> normals;
  std::array<int, kMaxFaces> faces{};
  int count = 0;
};

// The most contacts a surface reports for one grain (the buffers of the DEM solver).
inline constexpr int kMaxSurfaceContacts = 8;

class Surface {
 public:
  virtual ~Surface() = default;
  // The nearest point to `centre`; false when the centre lies farther than `reach` from the
  // surface on its material side (no contact possible), or, for some surfaces, where the
  // nearest point is not defined (said in their headers).
  virtual bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const = 0;

  // The contacts of a sphere centred at `centre` with gap <= `reach`, one per face it touches
  // (docs/dem.md, "Walls of several faces"), the deepest first when there are more than
  // out.size(); returns their number. The default: the nearest point, as face 0.
  virtual int contacts(const Vec3& centre, double reach, std::span<SurfacePoint> out) const;
  // The faces within `reach` of `centre`, at most out.size() (the nearest when there are more);
  // returns their number. The candidates of a grain that is not a sphere. The default: face 0
  // when nearest() finds a point with gap <= reach.
  virtual int faces_near(const Vec3& centre, double reach, std::span<int> out) const;
  // The nearest point of face `face` alone to `point` (a face is one smooth piece: a rectangle,
  // a disc, a cylinder's side, a triangle), with the face's normal and gap conventions; false
  // as nearest() says. The default: nearest() (the surface is one face).
  virtual bool nearest_on_face(int face, const Vec3& point, double reach, SurfacePoint& out) const;
  // Whether the contact `candidate` (on the boundary of its face) is a point of the face of
  // `deeper` too, so that it is not a contact of its own (docs/dem.md, "Walls of several faces").
  // The default: false (one face, or faces that never share a point a grain can touch).
  virtual bool shadowed(const SurfacePoint& candidate, const SurfacePoint& deeper) const;
  // Whether face `face`, as nearest_on_face() sees it, is a convex set (a plane, a rectangle):
  // then the plane through its point nearest a grain's centre, normal to the face's normal there,
  // separates the face from every grain whose extent along that normal falls short of the gap
  // (docs/dem.md, "Walls and superquadrics"). The default: false.
  virtual bool face_is_convex(int /*face*/) const { return false; }
  // Whether `at`, a point nearest_on_face() gave, lies on a convex edge or corner of its face,
  // and that edge or corner as `out`, with `at`'s face first. The default: false (none).
  virtual bool ridge(const SurfacePoint& /*at*/, Ridge& /*out*/) const { return false; }
  // The convex edges (as segments) and convex corners of three or more faces of face `face`
  // within `reach` of `centre`, at most out.size(); returns their number. The default: none.
  virtual int ridges_near(int /*face*/, const Vec3& /*centre*/, double /*reach*/,
                          std::span<Ridge> /*out*/) const {
    return 0;
  }
  // Whether faces a and b meet at a convex edge seen from the material side (near it the wall is
  // one convex solid, which a convex grain meets once). The default: false.
  virtual bool convex_neighbours(int /*face_a*/, int /*face_b*/) const { return false; }
  // The most contacts contacts() gives for one grain (slots in the DEM solver's contact history),
  // at most kMaxSurfaceContacts.
  virtual int max_contacts() const { return 1; }
};

}  // namespace partimix::geometry
