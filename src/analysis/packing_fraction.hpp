#pragma once
// Solid fraction of grains in an axis-aligned box (docs/mixing.md, "Packing fraction"):
//   phi = sum_{i: x_i in box} V_i / V_box,   V_i = the field "volume", else (4/3) pi R_i^3
// over the material particles whose centre lies in the box (faces included), each counted whole:
// grains cut by a face are not clipped, so phi is exact only on average and its error is of
// order (grains cut by the faces) / (grains inside). Superquadric grains carry their true volume
// in "volume" (their "radius" bounds them). A flat z side (2D runs) gives the area fraction of
// discs, sum pi R_i^2 / A_box. Needs the particle field "radius" or "volume" (DEM grains).
#include "analysis/analysis.hpp"

namespace partimix::analysis {

class PackingFraction final : public Analysis {
 public:
  // Throws std::invalid_argument unless hi > lo along x and y and hi.z >= lo.z.
  explicit PackingFraction(const PackingBox& box);
  std::vector<Column> columns() const override { return {{"packing_fraction", ""}}; }
  // Throws RunError when the particles have neither "radius" nor "volume".
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // packing_fraction_final: the last value (none before the first sample).
  void add_figures(Figures& figures) const override;

 private:
  double solid_in_box(const ParticleStore& particles) const;

  PackingBox box_;
  bool flat_;
  double measure_;  // the box's volume (area when flat)
  double last_;
};

}  // namespace partimix::analysis
