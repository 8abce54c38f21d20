#pragma once
// A cone frustum (a hopper) as a Shape: axis through `axis_point` along `axis` (normalised
// here), radius r0 at the axial coordinate z = 0 and r1 at z = height > 0, z = (x - axis_point)
// . axis. The solid frustum with its end discs; signed distance exact (negative inside): in the
// meridian plane (z, r) the distance to the nearest of the generator segment (0, r0)-(height,
// r1) and the two disc segments (0, 0)-(0, r0) and (height, 0)-(height, r1).
//
// It is a container whose two rims are always open: SPH lays wall layers outside the lateral
// surface only, none beyond z < 0 or z > height, for any axis direction (beyond_open_end). Its
// surface is a ConeSurface with the same parameters (lateral surface only), whose gap is minus
// the signed distance where the generator is the nearest part.
//
// Bounds: the bounding box of the two rim circles (a circle of radius r normal to the unit axis
// a spans r sqrt(1 - a_k^2) along axis k), which bounds the frustum, their convex hull.
#include "geometry/shape.hpp"

namespace partimix::geometry {

class Cone final : public Shape {
 public:
  Cone(const Vec3& axis_point, const Vec3& axis, double radius_0, double radius_1, double height);
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lower_; }
  Vec3 upper() const override { return upper_; }
  // Beyond either rim: z < 0 or z > height, whatever `open_faces` say.
  bool beyond_open_end(const Vec3& x, const std::vector<Face>& open_faces) const override;
  // A ConeSurface, whatever `solid` and `open_faces` say.
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;

 private:
  Vec3 axis_point_;
  Vec3 given_axis_;  // as given, so that the surface normalises the same vector
  Vec3 axis_;
  double radius_0_;
  double radius_1_;
  double height_;
  Vec3 lower_;
  Vec3 upper_;
};

}  // namespace partimix::geometry
