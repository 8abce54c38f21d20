#pragma once
// Sampling cells for the mixing measures (docs/mixing.md): a region cut into cells, and the map
// from a point to the index of the cell that holds it. The uniformity index and the Lacey index
// read per-cell particle counts tallied through this map, so they serve any region shape.
#include <array>
#include <memory>

#include "core/vec.hpp"

namespace partimix::analysis {

class SamplingCells {
 public:
  virtual ~SamplingCells() = default;
  // Index in [0, count()) of the cell holding x; -1 when x lies outside the region (or is NaN).
  virtual int cell_of(const Vec3& x) const = 0;
  virtual int count() const = 0;
};

// A solid cylinder: the axis passes through `axis_point` along `axis` (normalised on use); the
// axial coordinate z = (x - axis_point) . axis runs over [z0, z1].
struct CylinderRegion {
  Vec3 axis_point = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double radius = 1.0;
  double z0 = 0.0;
  double z1 = 1.0;
};

// A cylinder cut into n_r rings, n_theta sectors and n_z layers. Rings have equal area (ring k
// spans R sqrt(k / n_r) <= r < R sqrt((k + 1) / n_r)), sectors equal angle and layers equal
// height, so every cell holds the volume pi R^2 (z1 - z0) / (n_r n_theta n_z): a uniform random
// mixture then puts the same expected count in every cell, which eq. (S28) and the Lacey index
// assume. The angle theta in [0, 2 pi) is measured from reference() towards axis x reference().
// Cell index = (layer * n_theta + sector) * n_r + ring. The boundary r = R, z = z0, z = z1
// belongs to the region (to the outermost ring and the end layers).
class CylinderCells final : public SamplingCells {
 public:
  // Throws std::invalid_argument unless the axis is finite and non-zero, radius > 0, z1 > z0
  // and every division count is at least 1.
  CylinderCells(const CylinderRegion& region, int n_r, int n_theta, int n_z);
  int cell_of(const Vec3& x) const override;
  int count() const override { return n_r_ * n_theta_ * n_z_; }

  // Outer radius of ring k: R sqrt((k + 1) / n_r).
  double ring_outer_radius(int ring) const;
  // Unit vector normal to the axis where theta = 0: the coordinate axis least aligned with the
  // cylinder axis, made normal to it (x for an axis along z, so theta = atan2(y, x)).
  const Vec3& reference() const { return e1_; }
  const Vec3& axis() const { return axis_; }

 private:
  Vec3 origin_;
  Vec3 axis_;
  Vec3 e1_;
  Vec3 e2_;
  double radius_squared_;
  double z0_;
  double z1_;
  int n_r_;
  int n_theta_;
  int n_z_;
  double rings_per_radius_squared_;
  double sectors_per_radian_;
  double layers_per_length_;
};

// An axis-aligned box [lo, hi] cut into divisions[0] x divisions[1] x divisions[2] equal cells;
// cell index = (iz * ny + iy) * nx + ix. A flat side (lo = hi, as z in 2D runs, where every
// particle has z = 0) is allowed when it has one division. The faces belong to the region.
class BoxCells final : public SamplingCells {
 public:
  // Throws std::invalid_argument unless lo <= hi, every division count is at least 1 and every
  // flat side has one division.
  BoxCells(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& divisions);
  int cell_of(const Vec3& x) const override;
  int count() const override { return n_[0] * n_[1] * n_[2]; }

 private:
  Vec3 lo_;
  Vec3 hi_;
  std::array<int, 3> n_;
  Vec3 cells_per_length_;
};

// A sampling region and its cells, as a case file gives them (analyses of type mixing).
struct MixingRegion {
  bool cylinder = true;               // a cylinder (rings x sectors x layers) or a box
  CylinderRegion cylinder_region;     // cylinder
  Vec3 lo = Vec3::Zero();             // box
  Vec3 hi = Vec3::Zero();             // box
  std::array<int, 3> cells{1, 1, 1};  // rings, sectors, layers; or nx, ny, nz
  int min_count = 1;                  // Lacey: cells with fewer particles are not counted
};

// Throws std::invalid_argument for a region CylinderCells or BoxCells refuse.
std::unique_ptr<SamplingCells> make_sampling_cells(const MixingRegion& region);

}  // namespace partimix::analysis
