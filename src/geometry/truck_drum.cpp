#include "geometry/truck_drum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometry/meridian.hpp"

namespace partimix::geometry {
namespace {

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(name) + " must be above zero");
}

}  // namespace

TruckDrumGeometry::TruckDrumGeometry(const TruckDrumParameters& parameters) : p_(parameters) {
  require_positive(p_.head_radius, "head_radius");
  require_positive(p_.front_length, "front_length");
  require_positive(p_.radius, "radius");
  require_positive(p_.cylinder_length, "cylinder_length");
  require_positive(p_.rear_length, "rear_length");
  require_positive(p_.opening_radius, "opening_radius");
  require_positive(p_.blade_height, "blade_height");
  require_positive(p_.blade_thickness, "blade_thickness");
  if (p_.head_radius > p_.radius)
    throw std::invalid_argument("head_radius must not exceed radius");
  if (p_.opening_radius > p_.radius)
    throw std::invalid_argument("opening_radius must not exceed radius");
  if (p_.blade_height >= std::min(p_.head_radius, p_.opening_radius))
    throw std::invalid_argument("blade_height must be below head_radius and opening_radius");
  if (!(p_.helix_angle > 0.0 && p_.helix_angle < 0.5 * std::numbers::pi))
    throw std::invalid_argument("helix_angle must lie in (0, 90) degrees");
  starts_ = {0.0, p_.front_length, p_.front_length + p_.cylinder_length,
             p_.front_length + p_.cylinder_length + p_.rear_length};
  slopes_ = {(p_.radius - p_.head_radius) / p_.front_length, 0.0,
             (p_.opening_radius - p_.radius) / p_.rear_length};
}

int TruckDrumGeometry::segment(double z) const {
  if (z < starts_[1])
    return 0;
  return z < starts_[2] ? 1 : 2;
}

double TruckDrumGeometry::radius_at(double z) const {
  const double clamped = std::clamp(z, 0.0, length());
  const int s = segment(clamped);
  const double start_radius = s == 0 ? p_.head_radius : p_.radius;
  return start_radius + slopes_[s] * (clamped - starts_[s]);
}

// r dθ = tan β ds with ds = dz / cos α: dθ/dz = tan β / (r cos α), integrated from φ_s at z_s
// (docs/truck-drum.md, "Blades").
double TruckDrumGeometry::blade_angle(int s, double z) const {
  const double tan_beta = std::tan(p_.helix_angle);
  const double along = z - starts_[s];
  if (slopes_[s] == 0.0)
    return p_.offset_angles[s] + tan_beta * along / p_.radius;
  const double sin_alpha = slopes_[s] / std::sqrt(1.0 + slopes_[s] * slopes_[s]);
  return p_.offset_angles[s] +
         tan_beta / sin_alpha * std::log(radius_at(z) / radius_at(starts_[s]));
}

double TruckDrumGeometry::blade_twist(int s, double z) const {
  const double cos_alpha = 1.0 / std::sqrt(1.0 + slopes_[s] * slopes_[s]);
  return std::tan(p_.helix_angle) / (radius_at(z) * cos_alpha);
}

// The 2D signed distance of (z, ρ) to the meridian polygon; its edge along the axis is not a
// surface and is left out.
double TruckDrumGeometry::shell_distance(const Vec3& x) const {
  const double z = x.z();
  const double rho = std::hypot(x.x(), x.y());
  const double l = length();
  const double zc = starts_[2];
  double d = meridian_segment_distance(z, rho, 0.0, 0.0, 0.0, p_.head_radius);
  d = std::min(d, meridian_segment_distance(z, rho, 0.0, p_.head_radius, starts_[1], p_.radius));
  d = std::min(d, meridian_segment_distance(z, rho, starts_[1], p_.radius, zc, p_.radius));
  d = std::min(d, meridian_segment_distance(z, rho, zc, p_.radius, l, p_.opening_radius));
  d = std::min(d, meridian_segment_distance(z, rho, l, p_.opening_radius, l, 0.0));
  const bool inside = z > 0.0 && z < l && rho < radius_at(z);
  return inside ? -d : d;
}

// The nearer blade of segment s as a box across, along and out of its sheet (docs/truck-drum.md,
// "The blade's signed distance"); past the segment's ends, from its end section.
double TruckDrumGeometry::segment_blade_distance(int s, const Vec3& x) const {
  const double z = x.z();
  const double section = std::clamp(z, starts_[s], starts_[s + 1]);
  const double rho = std::hypot(x.x(), x.y());
  const double offset =
      std::remainder(std::atan2(x.y(), x.x()) - blade_angle(s, section), std::numbers::pi);
  const double twist = rho * blade_twist(s, section);
  const double across =
      std::abs(rho * offset / std::sqrt(1.0 + twist * twist)) - 0.5 * p_.blade_thickness;
  const double inward = radius_at(section) - p_.blade_height - rho;
  const double ends = std::max(starts_[s] - z, z - starts_[s + 1]);
  const Vec3 outside(std::max(across, 0.0), std::max(inward, 0.0), std::max(ends, 0.0));
  return outside.norm() + std::min(std::max({across, inward, ends}), 0.0);
}

// The nearest of all six blades: near a segment's end the next segment's blade may be nearer.
double TruckDrumGeometry::blade_distance(const Vec3& x) const {
  return std::min(
      {segment_blade_distance(0, x), segment_blade_distance(1, x), segment_blade_distance(2, x)});
}

double TruckDrumGeometry::signed_distance(const Vec3& x) const {
  return std::max(shell_distance(x), -blade_distance(x));
}

}  // namespace partimix::geometry
