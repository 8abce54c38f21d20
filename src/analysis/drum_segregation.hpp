#pragma once
// The segregation degree of the aggregate along a truck drum (docs/truck-drum.md, "Segregation
// degree"): the drum's length cut into `bins` equal axial slices; in slice k the coarse
// aggregate's share of the material's volume, phi_k = V_coarse,k / V_k, over the slices holding
// at least 5% of the mean slice's material; the degree is the coefficient of variation of phi_k
// in percent, S = 100 sd(phi) / mean(phi). Beside it S_r, the S a random mixture of the same
// grains would show (Lacey's binomial variance P (1 - P) / n per slice; docs/truck-drum.md). The
// summary gives S and S_r at the last sample at or before mixing_until, whether S is within the
// threshold (seed 004: 4), and with average_from the mean of S over the samples from then to
// mixing_until.
#include "analysis/analysis.hpp"
#include "analysis/drum_measures.hpp"

namespace partimix::analysis {

class DrumSegregation final : public Analysis {
 public:
  // Throws std::invalid_argument without a drum or with fewer than 2 bins.
  explicit DrumSegregation(const DrumMeasures& options);
  // segregation [%], coarse_fraction [-] (of all the material in the drum), segregation_random
  // [%].
  std::vector<Column> columns() const override {
    return {{"segregation", "%"}, {"coarse_fraction", ""}, {"segregation_random", "%"}};
  }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // segregation_degree [%], segregation_random [%], segregation_within_threshold (1 or 0), and
  // with average_from segregation_mean [%].
  void add_figures(Figures& figures) const override;

 private:
  void record(double time, double degree, double random);

  DrumMeasures options_;
  std::vector<double> coarse_;        // per slice, reused every sample: the coarse grains' volume,
  std::vector<double> all_;           // all grains' volume,
  std::vector<double> squares_;       // and the sum of their volumes' squares
  std::vector<std::size_t> counted_;  // the slices counted in the degree
  bool recorded_ = false;
  double degree_ = 0.0;
  double random_ = 0.0;
  double averaged_sum_ = 0.0;
  int averaged_ = 0;
};

}  // namespace partimix::analysis
