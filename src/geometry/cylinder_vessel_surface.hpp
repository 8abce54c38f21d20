#pragma once
// The inside of a closed circular cylinder along z (a vessel; the parameters of
// geometry::Cylinder: base centre, radius R, height H) as a contact surface, its bottom disc
// (face z-) and top disc (face z+) each closed unless open; other faces given are ignored. The
// material side is the inside (docs/dem.md, "Walls").
//
// Works in the meridian plane through the centre, (r, z) with r the distance from the axis and
// z the height above the base, where the side is the segment r = R, 0 <= z <= H and each closed
// disc the segment z = 0 or H, 0 <= r <= R. Returns the nearest point of those segments (side,
// then bottom, then top on a tie), mapped back to 3D (on the axis, r = 0, towards any radial
// direction).
// - Inside a segment (the side for 0 <= z <= H, a disc for r <= R): normal = its inward normal
//   (-e_r on the side, +z on the bottom, -z on the top), gap = the signed distance to it,
//   positive inside, negative for a centre that crossed it.
// - At a rim (the circle where side and disc meet, or the side's end at an open disc): normal
//   along the line from the rim to the centre, gap = -distance when the centre crossed the
//   closed surface (outside the cylinder, and not above an open top or below an open bottom),
//   else +distance (the rim of an opening, touched from either side).
// False when gap > reach.
//
// Faces (contacts(), docs/dem.md, "Walls of several faces"): 0 the side, 1 the bottom, 2 the top
// (when closed). The inside is convex, so every face a sphere touches gives a contact of its
// own. nearest_on_face() takes the side as the infinite cylinder r = R and a disc as its plane
// (normals -e_r, +z, -z, gap = the signed distance), except beyond an open disc, where the side
// ends at its rim circle (normal from the rim to the point, gap = +distance).
#include <span>
#include <vector>

#include "geometry/face.hpp"
#include "geometry/surface.hpp"

namespace partimix::geometry {

class CylinderVesselSurface final : public Surface {
 public:
  CylinderVesselSurface(const Vec3& base_centre, double radius, double height,
                        const std::vector<Face>& open_faces);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;
  int contacts(const Vec3& centre, double reach, std::span<SurfacePoint> out) const override;
  int faces_near(const Vec3& centre, double reach, std::span<int> out) const override;
  bool nearest_on_face(int face, const Vec3& point, double reach, SurfacePoint& out) const override;
  bool face_is_convex(int face) const override { return face != 0; }  // the discs' planes
  int max_contacts() const override { return 3; }

 private:
  // The faces' points (nearest_on_face) with gap <= reach, deepest first; their number.
  int face_points(const Vec3& centre, double reach, std::span<SurfacePoint, 3> out) const;
  SurfacePoint on_side(const Vec3& point) const;
  bool crossed(double r, double z) const;

  Vec3 base_;
  double radius_;
  double height_;
  bool bottom_closed_ = true;
  bool top_closed_ = true;
};

}  // namespace partimix::geometry
