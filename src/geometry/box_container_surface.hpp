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
#include <array>
#include <vector>

#include "geometry/face.hpp"
#include "geometry/surface.hpp"

namespace partimix::geometry {

class BoxContainerSurface final : public Surface {
 public:
  BoxContainerSurface(const Vec3& lo, const Vec3& hi, const std::vector<Face>& open_faces);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  bool crossed(const Vec3& centre) const;

  Vec3 lo_;
  Vec3 hi_;
  std::vector<Face> closed_faces_;               // in the tie order
  std::array<std::array<bool, 2>, 3> closed_{};  // [axis][side > 0]
};

}  // namespace partimix::geometry
