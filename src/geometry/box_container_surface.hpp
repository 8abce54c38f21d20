#pragma once
// The inside of an axis-aligned box [lo, hi] (a tank) as a contact surface, with some of its six
// faces open (the top of a tank); the material side is the inside. Each closed face is a
// rectangle; the surface is their union (docs/dem.md, "Walls").
//
// Returns the nearest point over the closed faces only: the centre clamped into the box, then
// moved onto the face's plane, for each closed face, and the nearest of these (the first in the
// order x-, x+, y-, y+, z-, z+ on a tie).
// - Inside a face (the centre lies within the face's rectangle seen along its axis): normal =
//   the face's inward normal, gap = the signed distance to the face's plane, positive inside the
//   box, negative for a centre that crossed that face. Inside the box this is the depth below
//   the nearest closed face.
// - On an edge or corner of a face (the centre lies outside the box, next to it): normal along
//   the line from the point to the centre, gap = -distance when the centre crossed the closed
//   faces (it is outside the box only across closed faces: overlap continues round a closed
//   edge or corner), else +distance (it is outside across an open face: it touches the rim of
//   the opening from either side, as the cone's rims do).
// A centre beyond an open face, farther than `reach` from every closed face, feels nothing.
// False when gap > reach, and always when every face is open.
//
// Faces (contacts(), docs/dem.md, "Walls of several faces"): face 2 axis + (side > 0), in the
// order above. The inside is convex, so every closed face a sphere touches gives a contact of
// its own. nearest_on_face() treats a face as its plane, extended across its closed edges (a
// point inside the box, or outside across closed faces: normal = the face's inward normal,
// gap = the signed distance to the plane), and as a rectangle at its edges with an open face (a
// point beyond an opening: the nearest point of the rectangle, on its rim, normal from the rim
// to the point, gap = +distance). A rim contact that is a point of a deeper face's rim too (a
// corner of the opening) is shadowed by it.
#include <array>
#include <vector>

#include "geometry/face.hpp"
#include "geometry/surface.hpp"

namespace partimix::geometry {

class BoxContainerSurface final : public Surface {
 public:
  BoxContainerSurface(const Vec3& lo, const Vec3& hi, const std::vector<Face>& open_faces);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;
  int contacts(const Vec3& centre, double reach, std::span<SurfacePoint> out) const override;
  int faces_near(const Vec3& centre, double reach, std::span<int> out) const override;
  bool nearest_on_face(int face, const Vec3& point, double reach, SurfacePoint& out) const override;
  bool shadowed(const SurfacePoint& candidate, const SurfacePoint& deeper) const override;
  // A grain inside a box wider than it touches three faces at most.
  bool face_is_convex(int /*face*/) const override { return true; }  // a plane or a rectangle
  int max_contacts() const override { return 3; }

 private:
  bool crossed(const Vec3& centre) const;
  // The closed faces' points (nearest_on_face) with gap <= reach; returns their number.
  int face_points(const Vec3& centre, double reach, std::span<SurfacePoint, 6> out) const;
  double plane(const Face& face) const { return face.side > 0 ? hi_[face.axis] : lo_[face.axis]; }

  Vec3 lo_;
  Vec3 hi_;
  std::vector<Face> closed_faces_;               // in the tie order
  std::array<std::array<bool, 2>, 3> closed_{};  // [axis][side > 0]
};

}  // namespace partimix::geometry
