#pragma once
// The pure measures of the droplet analysis (docs/multi-material-sph.md, "The scheme", droplet
// measurements; docs/case-reference.md, "analyses"): a shell's outline diameter, a particle's
// spacing-equivalent, a weighted mean and median, the sample nearest a time, and the labels of a
// shell's inner and outer surfaces.
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "analysis/shell_rupture.hpp"

namespace partimix::analysis {

// The outer diameter of a round shell whose inner and outer surface particles lie at the mean
// distances `inner` <= `outer` from its centre and whose particles' volumes sum to
// `shell_volume`: its surfaces lie half a layer t beyond those particles, t such that the ring
// (dimensions 2) or spherical shell (3) between inner - t/2 and outer + t/2 holds shell_volume.
// Returns 2 (outer + t/2); NaN unless inner, outer and shell_volume are finite and > 0.
double outline_diameter(double inner, double outer, double shell_volume, int dimensions);

// A particle's spacing-equivalent (m / rho)^(1/d), from its volume m / rho.
double spacing_equivalent(double volume, int dimensions);

// sum w_i v_i / sum w_i; NaN without weight.
class WeightedMean {
 public:
  void add(double value, double weight) {
    weighted_sum_ += weight * value;
    weight_ += weight;
  }
  double value() const;

 private:
  double weighted_sum_ = 0.0;
  double weight_ = 0.0;
};

// The weighted median of (value, weight > 0) pairs: the smallest value at which the weights of
// the values up to it reach half the total; NaN without pairs or with one not finite (which
// could not be sorted). Sorts `pairs` by value.
double weighted_median(std::vector<std::pair<double, double>>& pairs);

// Of the samples given in time order, the value of the one nearest `target` (the earlier of two
// as near), and whether a sample at or past the target has come: until then a later sample may
// be nearer.
class NearestSample {
 public:
  explicit NearestSample(double target) : target_(target) {}
  void add(double time, double value);
  bool reached() const { return reached_; }
  double value() const { return value_; }
  double target() const { return target_; }

 private:
  double target_;
  double distance_ = std::numeric_limits<double>::infinity();
  double value_ = std::numeric_limits<double>::quiet_NaN();
  bool reached_ = false;
};

// The surfaces of a shell from each shell particle's distance from the droplet's centroid and its
// spacing-equivalent: inner when within half its spacing of the smallest distance, else outer
// when within half its spacing of the largest, else none. A shell of one layer comes out all
// inner: it needs two layers or more to have both surfaces.
std::vector<ShellSurface> shell_surfaces(std::span<const double> distance,
                                         std::span<const double> spacing);

}  // namespace partimix::analysis
