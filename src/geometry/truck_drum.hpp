#pragma once
// The drum of a concrete truck mixer in its own frame (docs/truck-drum.md, "The drum in its own
// frame"): z along the axis from the closed head (z = 0) to the opening (z = L), a front cone, a
// cylinder and a rear cone, two blades on each segment half a turn apart, each a strip of the
// helicoid of radial lines along the curve that makes the helix angle β with the shell's
// generatrix. Signed distances, negative inside: the shell's cavity (exact: the 2D distance to
// the meridian polygon), the blades (exact sign, a distance to first order in the offset across
// the sheet), and the cavity the material fills, the shell's inside less the blades.
#include <array>

#include "core/vec.hpp"

namespace partimix::geometry {

struct TruckDrumParameters {
  double head_radius = 0.0;               // r_h [m], the front cone's radius at the closed head
  double front_length = 0.0;              // L_f [m]
  double radius = 0.0;                    // R [m], the cylinder's
  double cylinder_length = 0.0;           // L_c [m]
  double rear_length = 0.0;               // L_r [m]
  double opening_radius = 0.0;            // r_o [m], the rear cone's at the opening
  double helix_angle = 0.0;               // β [rad], with the generatrix
  double blade_height = 0.0;              // h_b [m], inwards from the shell
  double blade_thickness = 0.0;           // t_b [m]
  std::array<double, 3> offset_angles{};  // φ_s [rad], the first blade's angle at z_s
};

class TruckDrumGeometry {
 public:
  // Throws std::invalid_argument naming the parameter for a length or radius not above zero, an
  // opening or head wider than the cylinder, a blade as high as the narrowest radius, or a helix
  // angle outside (0, π/2).
  explicit TruckDrumGeometry(const TruckDrumParameters& parameters);

  const TruckDrumParameters& parameters() const { return p_; }
  double length() const { return starts_[3]; }
  // The segment of z: 0 front cone, 1 cylinder, 2 rear cone (z clamped to [0, L]).
  int segment(double z) const;
  double segment_start(int s) const { return starts_[s]; }
  // r(z), and the segment's slope dr/dz = tan α_s.
  double radius_at(double z) const;
  double slope(int s) const { return slopes_[s]; }
  // θ_s(z), the angle of segment s's first blade at z (the second is half a turn on).
  double blade_angle(int s, double z) const;
  // dθ_s/dz.
  double blade_twist(int s, double z) const;

  // x in the drum's frame.
  double shell_distance(const Vec3& x) const;
  double blade_distance(const Vec3& x) const;  // of the nearest of the six blades
  double signed_distance(const Vec3& x) const;

 private:
  double segment_blade_distance(int s, const Vec3& x) const;

  TruckDrumParameters p_;
  std::array<double, 4> starts_{};  // z_s of the segments, and L
  std::array<double, 3> slopes_{};  // tan α_s
};

}  // namespace partimix::geometry
