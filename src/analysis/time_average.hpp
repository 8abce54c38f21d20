#pragma once
// The time average of a sampled signal over a window, taking the signal as linear between
// samples (trapezoidal rule). Used for the summary figures of body loads and power numbers.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"
#include "analysis/averaging_window.hpp"

namespace partimix::analysis {

class SampledSignal {
 public:
  // Times must not decrease.
  void add(double time, double value);
  bool empty() const { return times_.empty(); }
  double first_time() const { return times_.front(); }
  double last_time() const { return times_.back(); }
  double last_value() const { return values_.back(); }
  // Mean over [from, to] clipped to the sampled span; the value itself for a single sample or
  // an empty window.
  double mean(double from, double to) const;

 private:
  std::vector<double> times_;
  std::vector<double> values_;
};

// The sampled history of an analysis' columns, for the summary: the mean of each column over
// the averaging window, under the column's name and with its unit, and the window as
// <prefix>average_from, <prefix>average_to [s] and <prefix>average_revolutions.
class ColumnHistory {
 public:
  explicit ColumnHistory(std::vector<Column> columns) : columns_(std::move(columns)) {
    signals_.resize(columns_.size());
  }
  void add(double time, std::span<const double> values);
  void add_figures(Figures& figures, const std::string& prefix, double period,
                   double revolutions) const;
  // A caveat on each mean whose window holds fewer than `revolutions` periods (the run was
  // shorter) or starts before `ramp_time` (it takes in the start-up ramp).
  void add_caveats(std::map<std::string, std::string>& caveats, double period, double revolutions,
                   double ramp_time) const;

 private:
  std::vector<Column> columns_;
  std::vector<SampledSignal> signals_;
};

}  // namespace partimix::analysis
