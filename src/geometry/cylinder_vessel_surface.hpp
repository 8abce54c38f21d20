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
#include <vector>

#include "geometry/face.hpp"
#include "geometry/surface.hpp"

namespace partimix::geometry {

class CylinderVesselSurface final : public Surface {
 public:
  CylinderVesselSurface(const Vec3& base_centre, double radius, double height,
                        const std::vector<Face>& open_faces);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  bool crossed(double r, double z) const;

  Vec3 base_;
  double radius_;
  double height_;
  bool bottom_closed_ = true;
  bool top_closed_ = true;
};

}  // namespace partimix::geometry
