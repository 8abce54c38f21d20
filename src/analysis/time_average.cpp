#include "analysis/time_average.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace partimix::analysis {

void SampledSignal::add(double time, double value) {
  times_.push_back(time);
  values_.push_back(value);
}

double SampledSignal::mean(double from, double to) const {
  from = std::max(from, times_.front());
  to = std::min(to, times_.back());
  double integral = 0.0;
  for (std::size_t k = 1; k < times_.size(); ++k) {
    const double t0 = times_[k - 1];
    const double t1 = times_[k];
    const double a = std::max(t0, from);
    const double b = std::min(t1, to);
    if (!(b > a) || !(t1 > t0))
      continue;
    const auto value_at = [&](double t) {
      return values_[k - 1] + (values_[k] - values_[k - 1]) * (t - t0) / (t1 - t0);
    };
    integral += 0.5 * (value_at(a) + value_at(b)) * (b - a);
  }
  if (!(to > from))
    return values_.back();
  return integral / (to - from);
}

void ColumnHistory::add(double time, std::span<const double> values) {
  for (std::size_t k = 0; k < signals_.size(); ++k)
    signals_[k].add(time, values[k]);
}

void ColumnHistory::add_figures(Figures& figures, const std::string& prefix, double period,
                                double revolutions) const {
  if (signals_.empty() || signals_.front().empty())
    return;
  const AveragingWindow window = averaging_window(
      signals_.front().first_time(), signals_.front().last_time(), period, revolutions);
  for (std::size_t k = 0; k < signals_.size(); ++k)
    figures.add(columns_[k].name, signals_[k].mean(window.from, window.to), columns_[k].unit);
  figures.add(prefix + "average_from", window.from, "s");
  figures.add(prefix + "average_to", window.to, "s");
  figures.add(prefix + "average_revolutions", window.revolutions, "");
}

void ColumnHistory::add_caveats(std::map<std::string, std::string>& caveats, double period,
                                double revolutions, double ramp_time) const {
  if (signals_.empty() || signals_.front().empty())
    return;
  const AveragingWindow window = averaging_window(
      signals_.front().first_time(), signals_.front().last_time(), period, revolutions);
  const bool short_window = period > 0.0 && window.revolutions < revolutions * (1.0 - 1e-9);
  const bool in_ramp = window.from < ramp_time;
  if (!short_window && !in_ramp)
    return;
  std::string reason = fmt::format("averaged over t = {:.4g} to {:.4g} s", window.from, window.to);
  if (short_window)
    reason +=
        fmt::format(", {:.3g} of the {:.3g} revolutions asked", window.revolutions, revolutions);
  if (in_ramp)
    reason += fmt::format(", which takes in the start-up ramp (ramp_time {:.4g} s)", ramp_time);
  reason += fmt::format("; run to at least t = {:.4g} s for a full window after the ramp",
                        ramp_time + revolutions * period);
  for (const Column& column : columns_)
    caveats[column.name] = reason;
}

}  // namespace partimix::analysis
