#pragma once
// Mass of material in a box and its discharge rate (docs/mixing.md, "Mass in a region and
// discharge rate"): every sample, the mass M(t) of the material particles whose position lies in
// the axis-aligned box [lo, hi] (faces included), and the flow out of it since the previous
// sample, -(M(t) - M(t_prev)) / (t - t_prev) (0 at the first sample). The summary gives the last
// M and the discharge rate W = -b, b the slope of the least-squares line through the samples
// (t, M) with fit_from <= t <= fit_until: a silo's steady discharge (Beverloo), free of the
// start-up and of the end when the silo runs empty.
#include "analysis/analysis.hpp"
#include "analysis/running_line_fit.hpp"

namespace partimix::analysis {

// Samples in the fit window that a discharge rate needs.
inline constexpr int kMinDischargeSamples = 3;

class MassInRegion final : public Analysis {
 public:
  // Throws std::invalid_argument unless hi > lo along x and y, hi.z >= lo.z and
  // fit_from < fit_until.
  explicit MassInRegion(const MassRegion& region);
  // mass [kg], mass_flow [kg/s].
  std::vector<Column> columns() const override { return {{"mass", "kg"}, {"mass_flow", "kg/s"}}; }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // mass_final [kg] (after the first sample); discharge_rate [kg/s] (with at least
  // kMinDischargeSamples samples in the fit window).
  void add_figures(Figures& figures) const override;
  // discharge_rate: why it is missing, when too few samples lie in the fit window.
  void add_caveats(Caveats& caveats) const override;

 private:
  double mass_inside(const ParticleStore& particles) const;
  // The history: the last sample, and the sample in the fit when it lies in the window.
  void record(double time, double mass);

  MassRegion region_;
  RunningLineFit fit_;
  bool sampled_ = false;
  double last_time_ = 0.0;
  double last_mass_ = 0.0;
};

}  // namespace partimix::analysis
