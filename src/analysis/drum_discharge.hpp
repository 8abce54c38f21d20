#pragma once
// A truck drum's discharge (docs/truck-drum.md, "Discharge and uniformity"): every sample, the
// volume of material (the grains' solid volume) within the shell's cavity, V(t), what has left
// it since the first sample, D = V(0) - V(t), the flow since the previous sample [m³/min], and the
// stream just past the opening (the axial span (L, L + 2 r_o]): its material volume and the
// coarse aggregate's share of it. The summary: the residual rate 100 V_end / V(0) [%]; the
// discharge rate, 60 times the slope of the least-squares line through (t, D) over the samples in
// [fit_from, fit_until] [m³/min]; and the uniformity test's relative difference of the coarse
// aggregate between two samples of the stream, taken while D is 20-30% and 70-80% of the volume
// discharged by the end, 100 |a - b| / ((a + b) / 2) with a, b the coarse shares of all the
// stream volume sampled in each. Any particles with a volume will do: grains (their solid
// volume), MPM points, or a grid fluid's cells (the fluid's volume in each, with two phases the
// heavy one's: the mortar); particles without `species` are not coarse aggregate.
#include <vector>

#include "analysis/analysis.hpp"
#include "analysis/drum_measures.hpp"
#include "analysis/running_line_fit.hpp"

namespace partimix::analysis {

class DrumDischarge final : public Analysis {
 public:
  // Throws std::invalid_argument without a drum or with fit_until not after fit_from.
  explicit DrumDischarge(const DrumMeasures& options);
  std::vector<Column> columns() const override {
    return {{"retained_volume", "m^3"},
            {"discharged_volume", "m^3"},
            {"discharge_flow", "m^3/min"},
            {"stream_volume", "m^3"},
            {"stream_coarse_fraction", ""}};
  }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // residual_rate [%]; discharge_rate [m³/min] (with at least 3 samples in the fit window);
  // coarse_aggregate_difference [%] (when both stream samples hold material).
  void add_figures(Figures& figures) const override;
  void add_caveats(Caveats& caveats) const override;

 private:
  struct StreamSample {
    double discharged;  // D [m³]
    double volume;      // the stream's material [m³]
    double coarse;      // its coarse aggregate [m³]
  };
  void record(double time, std::span<const double> values);
  // The coarse share of the stream over the samples with D in [from, to] times D_end; NaN when
  // they hold no material.
  double stream_share(double from, double to) const;

  DrumMeasures options_;
  RunningLineFit fit_;
  std::vector<StreamSample> stream_;
  bool sampled_ = false;
  double first_volume_ = 0.0;
  double last_time_ = 0.0;
  double last_volume_ = 0.0;
};

}  // namespace partimix::analysis
