#pragma once
// Mixing of a tracer in the material (fluid or grains) (docs/mixing.md): the uniformity index xi
// (seed eq. 28) and the Lacey index M over sampling cells, each sample. Tracer particles carry tag
// 1, the rest of the mixture tag 0; wall particles are not counted. The summary gives the last
// values and the mixing rate: fits of the sampled M(t) to the exponential, error-function and
// diffusive models (analysis/mixing_rate.hpp), when there are enough finite samples to fit.
#include <memory>
#include <vector>

#include "analysis/analysis.hpp"
#include "analysis/mixing_index.hpp"
#include "analysis/sampling_cells.hpp"

namespace partimix::analysis {

class Mixing final : public Analysis {
 public:
  explicit Mixing(const MixingRegion& region);
  std::vector<Column> columns() const override { return {{"xi", ""}, {"lacey", ""}}; }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  void add_figures(Figures& figures) const override;

 private:
  std::unique_ptr<SamplingCells> cells_;
  int min_count_;
  CellCounts counts_;
  std::vector<MixingRole> roles_;
  std::vector<double> times_;   // every sample's time [s]
  std::vector<double> laceys_;  // and its Lacey index (NaN ones included; the fits skip them)
  double last_xi_ = LaceyResult::nan;
  double last_lacey_ = LaceyResult::nan;
};

}  // namespace partimix::analysis
