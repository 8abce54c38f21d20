#pragma once
// An infinite plane through `point` with `normal` (normalised here) pointing towards the
// material, as a Shape: the solid half-space behind the plane, signed distance
// (x - point) . normal (negative behind). SPH lays a solid wall's layers behind it
// (inside_layers); its surface is a PlaneSurface with the same point and normal, whose gap
// equals the signed distance.
//
// Bounds: -/+infinity on every axis, except for a plane normal to a coordinate axis, whose
// half-space ends at the plane along that axis. The lattice samplers cut infinite bounds at the
// domain.
#include "geometry/shape.hpp"

namespace partimix::geometry {

class Plane final : public Shape {
 public:
  Plane(const Vec3& point, const Vec3& normal);
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lower_; }
  Vec3 upper() const override { return upper_; }
  // A plane has no end to leave open.
  bool beyond_open_end(const Vec3&, const std::vector<Face>&) const override { return false; }
  // A PlaneSurface, whatever `solid` and `open_faces` say.
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;

 private:
  Vec3 point_;
  Vec3 given_normal_;  // as given, so that the surface normalises the same vector
  Vec3 normal_;
  Vec3 lower_;
  Vec3 upper_;
};

}  // namespace partimix::geometry
