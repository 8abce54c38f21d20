#pragma once
// The mass flow rate through a plane (docs/mixing.md, "Mass flux through a plane"): the
// material particles within the band |(x - point) . n| < width / 2 carry
//   Q = sum_p m_p (v_p . n) / width     [kg/s; kg/(s m) in a 2D run]
// across the plane, the band's mass flux averaged over its width (the estimator of a flux from
// particles: Q dt is the mass that crosses the plane in dt when the band is uniform). The
// summary gives the mean of Q over the samples from average_from on: a hopper's steady mass
// flow.
#include "analysis/analysis.hpp"

namespace partimix::analysis {

class MassFlux final : public Analysis {
 public:
  // Throws std::invalid_argument unless width > 0 and the normal is a unit vector.
  explicit MassFlux(const FluxPlane& plane);
  std::vector<Column> columns() const override { return {{"mass_flux", "kg/s"}}; }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // mean_mass_flux [kg/s] over the samples from average_from on (when there is one).
  void add_figures(Figures& figures) const override;

 private:
  void record(double time, double flux);

  FluxPlane plane_;
  double sum_ = 0.0;
  int count_ = 0;
};

}  // namespace partimix::analysis
