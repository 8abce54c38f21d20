#pragma once
// A drum as a Shape: the solid infinite circular cylinder of radius R_d about the axis through
// `axis_point` along `axis` (normalised here), signed distance r - R_d with r the distance from
// the axis (negative inside). It is a container, the material inside: SPH lays wall layers
// outside it (wall_layers), with no open end; its surface is a DrumSurface with the same
// parameters, whose gap R_d - r is minus the signed distance.
//
// Bounds: finite (axis_point -/+ R_d) only along the coordinate axes normal to the drum's axis
// (axis component exactly zero), -/+infinity along the others; the lattice samplers cut those at
// the domain, so that the drum's ends are the domain's (periodic, or closed by other walls).
#include "geometry/shape.hpp"

namespace partimix::geometry {

class Drum final : public Shape {
 public:
  Drum(const Vec3& axis_point, const Vec3& axis, double radius);
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lower_; }
  Vec3 upper() const override { return upper_; }
  // An infinite drum has no end to leave open.
  bool beyond_open_end(const Vec3&, const std::vector<Face>&) const override { return false; }
  // A DrumSurface, whatever `solid` and `open_faces` say.
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;

 private:
  Vec3 axis_point_;
  Vec3 given_axis_;  // as given, so that the surface normalises the same vector
  Vec3 axis_;
  double radius_;
  Vec3 lower_;
  Vec3 upper_;
};

}  // namespace partimix::geometry
