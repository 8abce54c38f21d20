#pragma once
// Height of the material's top surface along a line (docs/mixing.md, "Height profile"): the
// span [from, to] of the coordinate `axis` is cut into n equal bins; a material particle whose
// `axis` coordinate s lies in [from, to] falls in bin floor((s - from) n / (to - from)) (s = to in
// the last), whatever its other coordinates. Each bin reports the largest `vertical` coordinate
// of its particles, NaN when it is empty. The deposit of a collapsed granular column: its height
// profile, its largest height and its runout.
#include <vector>

#include "analysis/analysis.hpp"

namespace partimix::analysis {

class HeightProfile final : public Analysis {
 public:
  // Throws std::invalid_argument unless axis and vertical are distinct axes (0, 1, 2),
  // to > from and bins >= 1.
  explicit HeightProfile(const HeightLine& line);
  // height_0 ... height_<n-1> [m].
  std::vector<Column> columns() const override;
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // Of the last sample, when a bin is not empty: height_max [m], the largest height, and
  // runout [m], the upper edge from + (k + 1) (to - from) / n of the last bin k that is not empty.
  void add_figures(Figures& figures) const override;

 private:
  // The bin of the coordinate s; -1 outside [from, to].
  int bin_of(double s) const;

  HeightLine line_;
  double bins_per_length_;
  std::vector<double> last_;  // per bin, the last sample (NaN when empty); sized at set-up
};

}  // namespace partimix::analysis
