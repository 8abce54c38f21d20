#pragma once
// The orientation order of elongated grains (docs/mixing.md, "Orientation order"). With u_i the
// unit axis of grain i (grain_axis below) and e_i the reference direction (a fixed direction or
// grain i's direction of motion):
//   alignment      S_dir = < P2(u_i . e_i) > = < (3 (u_i . e_i)^2 - 1) / 2 >
//   nematic_order  S     = the largest eigenvalue of Q = < (3 u_i u_i^T - I) / 2 >
// both 1 for grains all along one line (along e for S_dir), and S_dir = -1/2 for grains all
// normal to e. Averages over the material particles that have an axis; needs the particle
// fields orientation_w, orientation_v and half_axes (DEM runs with superquadric species).
#include "analysis/analysis.hpp"

namespace partimix::analysis {

// The body axis (0, 1, 2 for x, y, z) of grain of half-axes `half_axes`: that of the largest
// half-axis when it is the only largest (a prolate or triaxial grain: its long axis), else that
// of the smallest when it is the only smallest (an oblate grain: its symmetry axis), else -1 (a
// sphere, or equal half-axes: no axis).
int grain_axis(const Vec3& half_axes);

class OrientationOrder final : public Analysis {
 public:
  // Throws std::invalid_argument for a zero direction or a negative min_speed.
  explicit OrientationOrder(const OrientationReference& reference);
  std::vector<Column> columns() const override {
    return {{"alignment", ""}, {"nematic_order", ""}};
  }
  // NaN for an average over no grain. Throws RunError when the particles lack the fields.
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // alignment_final and nematic_order_final: the last values (none while NaN).
  void add_figures(Figures& figures) const override;

 private:
  Vec3 velocity_of(const ParticleStore& particles, std::size_t i) const;

  OrientationReference reference_;
  double alignment_;
  double nematic_order_;
};

}  // namespace partimix::analysis
