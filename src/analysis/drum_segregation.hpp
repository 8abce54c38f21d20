#pragma once
// The segregation degree of the aggregate along a truck drum (docs/truck-drum.md, "Segregation
// degree"): the drum's length cut into `bins` equal axial slices; in slice k the coarse
// aggregate's share of the material's volume, phi_k = V_coarse,k / V_k, over the slices holding
// at least 5% of the mean slice's material; the degree is the coefficient of variation of phi_k
// in percent, S = 100 sd(phi) / mean(phi). The summary gives S at the last sample at or before
// mixing_until, and whether it is within the threshold (seed 004: 4).
#include "analysis/analysis.hpp"
#include "analysis/drum_measures.hpp"

namespace partimix::analysis {

class DrumSegregation final : public Analysis {
 public:
  // Throws std::invalid_argument without a drum or with fewer than 2 bins.
  explicit DrumSegregation(const DrumMeasures& options);
  // segregation [%], coarse_fraction [-] (of all the material in the drum).
  std::vector<Column> columns() const override {
    return {{"segregation", "%"}, {"coarse_fraction", ""}};
  }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // segregation_degree [%], segregation_within_threshold (1 or 0).
  void add_figures(Figures& figures) const override;

 private:
  void record(double time, double degree);

  DrumMeasures options_;
  std::vector<double> coarse_;  // per slice, reused every sample
  std::vector<double> all_;
  bool recorded_ = false;
  double degree_ = 0.0;
};

}  // namespace partimix::analysis
