#include "analysis/sampling_cells.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace partimix::analysis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Bin of a scaled coordinate t in [0, n]: t = n (the far boundary, which belongs to the
// region) falls in the last bin rather than past it.
int bin(double t, int n) {
  return std::min(static_cast<int>(t), n - 1);
}

void require_divisions(int n, const char* what) {
  if (n < 1)
    throw std::invalid_argument(std::string("sampling cells: ") + what +
                                " must be at least 1, got " + std::to_string(n));
}

Vec3 unit_axis(const Vec3& axis) {
  const double length = axis.norm();
  if (!std::isfinite(length) || length == 0.0)
    throw std::invalid_argument("sampling cells: cylinder axis must be finite and non-zero");
  return axis / length;
}

// The coordinate axis least aligned with `axis`, with its component along `axis` removed: a
// fixed rule, so that the sectors of a given cylinder are always the same.
Vec3 reference_direction(const Vec3& axis) {
  Eigen::Index least = 0;
  axis.cwiseAbs().minCoeff(&least);
  const Vec3 e = Vec3::Unit(least);
  return (e - e.dot(axis) * axis).normalized();
}

}  // namespace

CylinderCells::CylinderCells(const CylinderRegion& region, int n_r, int n_theta, int n_z)
    : origin_(region.axis_point),
      axis_(unit_axis(region.axis)),
      e1_(reference_direction(axis_)),
      e2_(axis_.cross(e1_)),
      radius_squared_(region.radius * region.radius),
      z0_(region.z0),
      z1_(region.z1),
      n_r_(n_r),
      n_theta_(n_theta),
      n_z_(n_z) {
  if (!(region.radius > 0.0) || !std::isfinite(region.radius))
    throw std::invalid_argument("sampling cells: cylinder radius must be positive");
  if (!(region.z1 > region.z0) || !std::isfinite(region.z1 - region.z0))
    throw std::invalid_argument("sampling cells: cylinder needs z1 > z0");
  require_divisions(n_r, "n_r");
  require_divisions(n_theta, "n_theta");
  require_divisions(n_z, "n_z");
  // Equal-area rings: the area inside radius r is proportional to r^2, so the ring index is
  // r^2 scaled by n_r / R^2 and rounded down.
  rings_per_radius_squared_ = n_r / radius_squared_;
  sectors_per_radian_ = n_theta / kTwoPi;
  layers_per_length_ = n_z / (z1_ - z0_);
}

int CylinderCells::cell_of(const Vec3& x) const {
  const Vec3 d = x - origin_;
  const double z = d.dot(axis_);
  if (!(z >= z0_ && z <= z1_))
    return -1;
  const double u = d.dot(e1_);
  const double v = d.dot(e2_);
  const double r_squared = u * u + v * v;
  if (!(r_squared <= radius_squared_))
    return -1;
  double theta = std::atan2(v, u);
  if (theta < 0.0)
    theta += kTwoPi;
  const int ring = bin(r_squared * rings_per_radius_squared_, n_r_);
  const int sector = bin(theta * sectors_per_radian_, n_theta_);
  const int layer = bin((z - z0_) * layers_per_length_, n_z_);
  return (layer * n_theta_ + sector) * n_r_ + ring;
}

double CylinderCells::ring_outer_radius(int ring) const {
  return std::sqrt(radius_squared_ * (ring + 1) / n_r_);
}

BoxCells::BoxCells(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& divisions)
    : lo_(lo), hi_(hi), n_(divisions), cells_per_length_(Vec3::Zero()) {
  static const char* const names[] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a) {
    require_divisions(n_[a], names[a]);
    if (!(hi[a] >= lo[a]) || !std::isfinite(hi[a] - lo[a]))
      throw std::invalid_argument("sampling cells: box needs lo <= hi on every axis");
    if (hi[a] == lo[a] && n_[a] != 1)
      throw std::invalid_argument(std::string("sampling cells: a flat box side needs ") + names[a] +
                                  " = 1");
    // A flat side keeps zero here, so every point on it falls in its single division.
    if (hi[a] > lo[a])
      cells_per_length_[a] = n_[a] / (hi[a] - lo[a]);
  }
}

int BoxCells::cell_of(const Vec3& x) const {
  int index = 0;
  for (int a = 2; a >= 0; --a) {
    if (!(x[a] >= lo_[a] && x[a] <= hi_[a]))
      return -1;
    index = index * n_[a] + bin((x[a] - lo_[a]) * cells_per_length_[a], n_[a]);
  }
  return index;
}

std::unique_ptr<SamplingCells> make_sampling_cells(const MixingRegion& region) {
  const auto& n = region.cells;
  if (region.cylinder)
    return std::make_unique<CylinderCells>(region.cylinder_region, n[0], n[1], n[2]);
  return std::make_unique<BoxCells>(region.lo, region.hi, n);
}

}  // namespace partimix::analysis
