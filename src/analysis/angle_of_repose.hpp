#pragma once
// Dynamic angle of repose of a bed in a drum (docs/mixing.md, "Dynamic angle of repose"). The
// material particles are projected onto the plane normal to the drum axis a (through `centre`),
// with
//   up u = -(down - (down . a) a) / |...|   (gravity's part normal to the axis, reversed),
//   horizontal h = u x a                    (normal to the axis and to gravity),
// coordinates x = (p - centre) . h and y = (p - centre) . u. The bed's extent [x_min, x_max] is
// cut into `bins` equal bins; in each, the particle with the largest y is a free-surface point.
// A straight line y = a + b x is fitted by least squares to the surface points with
// x_min + trim W <= x <= x_max - trim W (W = x_max - x_min), and the angle is atan(|b|) in
// degrees. NaN when fewer than two such points (or points at one x) remain.
#include <vector>

#include "analysis/analysis.hpp"

namespace partimix::analysis {

class AngleOfRepose final : public Analysis {
 public:
  // Throws std::invalid_argument unless the axis is finite and non-zero, `down` has a non-zero
  // part normal to it, bins >= 2 and 0 <= trim < 0.5.
  explicit AngleOfRepose(const ReposeSection& section);
  std::vector<Column> columns() const override { return {{"angle_of_repose", "deg"}}; }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // angle_of_repose_final: the last value [deg], when it is not NaN.
  void add_figures(Figures& figures) const override;

  const Vec3& horizontal() const { return horizontal_; }
  const Vec3& up() const { return up_; }

 private:
  ReposeSection section_;
  Vec3 up_;
  Vec3 horizontal_;
  std::vector<double> top_x_;  // per bin: x and y of the highest particle; sized at set-up
  std::vector<double> top_y_;
  std::vector<char> filled_;
  double last_;
};

}  // namespace partimix::analysis
