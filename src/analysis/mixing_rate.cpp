#include "analysis/mixing_rate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace partimix::analysis {
namespace {

bool valid(double time, double value) {
  return std::isfinite(time) && std::isfinite(value);
}

// What the fit needs of the samples, whatever k: their count, t_0, the smallest positive and the
// largest t - t_0, the mean value and the total sum of squares about it.
struct SampleSummary {
  int count = 0;
  double start = 0.0;
  double first_step = 0.0;  // tau_1: the smallest positive t - t_0 (0 when none)
  double span = 0.0;        // T: the largest t - t_0
  double mean = 0.0;
  double total_squares = 0.0;
};

SampleSummary summarise(std::span<const double> times, std::span<const double> values) {
  SampleSummary s;
  double sum = 0.0;
  double first = 0.0;
  double last = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!valid(times[i], values[i]))
      continue;
    if (s.count == 0) {
      first = times[i];
      last = times[i];
    }
    first = std::min(first, times[i]);
    last = std::max(last, times[i]);
    sum += values[i];
    ++s.count;
  }
  if (s.count == 0)
    return s;
  s.start = first;
  s.span = last - first;
  s.mean = sum / s.count;
  double first_step = s.span;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!valid(times[i], values[i]))
      continue;
    const double tau = times[i] - first;
    if (tau > 0.0)
      first_step = std::min(first_step, tau);
    const double m = values[i] - s.mean;
    s.total_squares += m * m;
  }
  s.first_step = first_step;
  return s;
}

// The linear least-squares fit M = M_0 + (M_f - M_0) h at one rate k, with M_f <= M_max.
struct LinearFit {
  double squares = 0.0;  // SS_res
  double initial = 0.0;  // M_0
  double plateau = 0.0;  // M_f
  bool bounded = false;  // M_f held at M_max
  bool ok = false;
};

// h_j = h(k (t_j - t_0)) of the valid samples, one at a time.
template <typename Visit>
void for_each_sample(std::span<const double> times, std::span<const double> values,
                     const SampleSummary& s, MixingModel model, double rate, Visit&& visit) {
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (valid(times[i], values[i]))
      visit(mixing_approach(model, rate * (times[i] - s.start)), values[i]);
  }
}

// With M_f held at M_max: M - M_max h = M_0 (1 - h), one parameter. The first sample has h = 0,
// so the sum of (1 - h)^2 is at least 1.
LinearFit fit_with_plateau(std::span<const double> times, std::span<const double> values,
                           const SampleSummary& s, MixingModel model, double rate, double plateau) {
  double sum_gg = 0.0;
  double sum_gy = 0.0;
  for_each_sample(times, values, s, model, rate, [&](double h, double m) {
    sum_gg += (1.0 - h) * (1.0 - h);
    sum_gy += (1.0 - h) * (m - plateau * h);
  });
  LinearFit fit;
  fit.initial = sum_gy / sum_gg;
  fit.plateau = plateau;
  fit.bounded = true;
  for_each_sample(times, values, s, model, rate, [&](double h, double m) {
    const double r = m - fit.initial * (1.0 - h) - plateau * h;
    fit.squares += r * r;
  });
  fit.ok = true;
  return fit;
}

LinearFit fit_at(std::span<const double> times, std::span<const double> values,
                 const SampleSummary& s, MixingModel model, double rate, double plateau_max) {
  // With m_i = M_i - mean(M), sum m_i = 0, so S_hm = sum (h_i - mean h) m_i = sum h_i m_i. h lies
  // in [0, 1] and is small for small k, so S_hh = sum h^2 - (sum h)^2 / n keeps its digits.
  double sum_h = 0.0;
  double sum_hh = 0.0;
  double sum_hm = 0.0;
  for_each_sample(times, values, s, model, rate, [&](double h, double m) {
    sum_h += h;
    sum_hh += h * h;
    sum_hm += h * (m - s.mean);
  });
  LinearFit fit;
  const double mean_h = sum_h / s.count;
  const double s_hh = sum_hh - sum_h * mean_h;
  if (!(s_hh > 0.0)) {
    fit.squares = s.total_squares;
    return fit;
  }
  const double slope = sum_hm / s_hh;  // M_f - M_0
  fit.initial = s.mean - slope * mean_h;
  fit.plateau = fit.initial + slope;
  if (fit.plateau > plateau_max)
    return fit_with_plateau(times, values, s, model, rate, plateau_max);
  // SS_res summed from the residuals, not as SS_tot - S_hm^2 / S_hh: near the best k that
  // difference loses the digits the search needs to place k.
  const double intercept = -slope * mean_h;  // of the centred values m_i
  for_each_sample(times, values, s, model, rate, [&](double h, double m) {
    const double r = m - s.mean - intercept - slope * h;
    fit.squares += r * r;
  });
  fit.ok = true;
  return fit;
}

}  // namespace

double mixing_approach(MixingModel model, double x) {
  switch (model) {
    case MixingModel::exponential:
      return -std::expm1(-x);
    case MixingModel::error_function:
      return std::erf(x);
    case MixingModel::diffusive:
      break;
  }
  return std::erf(std::sqrt(x));
}

double mixing_model_value(MixingModel model, const MixingRateFit& fit, double time) {
  if (fit.status != MixingFitStatus::ok || !(time >= fit.start_time))
    return MixingRateFit::nan;
  return fit.initial +
         (fit.plateau - fit.initial) * mixing_approach(model, fit.rate * (time - fit.start_time));
}

std::string mixing_model_suffix(MixingModel model) {
  switch (model) {
    case MixingModel::exponential:
      return "exp";
    case MixingModel::error_function:
      return "erf";
    case MixingModel::diffusive:
      break;
  }
  return "diffusive";
}

MixingRateFit fit_mixing_rate(std::span<const double> times, std::span<const double> values,
                              MixingModel model, double plateau_max) {
  if (times.size() != values.size())
    throw std::invalid_argument("fit_mixing_rate: times and values differ in length");
  MixingRateFit result;
  const SampleSummary s = summarise(times, values);
  result.samples = s.count;
  if (s.count < kMinMixingFitSamples) {
    result.status = MixingFitStatus::too_few_samples;
    return result;
  }
  result.start_time = s.start;
  if (!(s.span > 0.0)) {
    result.status = MixingFitStatus::no_time_spread;
    return result;
  }
  if (!(s.total_squares > 0.0)) {
    result.status = MixingFitStatus::flat;
    result.initial = s.mean;
    result.plateau = s.mean;
    result.rms = 0.0;
    return result;
  }

  // Scan ln k on a grid of ten points per decade, then refine about the best point by a
  // golden-section search over its two neighbouring intervals.
  const double ln_lo = std::log(1.0e-3 / s.span);
  const double ln_hi = std::log(50.0 / s.first_step);
  const double step = std::log(10.0) / 10.0;
  const int points = std::max(2, static_cast<int>(std::ceil((ln_hi - ln_lo) / step)) + 1);
  const double grid_step = (ln_hi - ln_lo) / (points - 1);
  auto squares_at = [&](double ln_k) {
    return fit_at(times, values, s, model, std::exp(ln_k), plateau_max).squares;
  };
  int best = 0;
  double best_squares = squares_at(ln_lo);
  for (int j = 1; j < points; ++j) {
    const double squares = squares_at(ln_lo + j * grid_step);
    if (squares < best_squares) {
      best_squares = squares;
      best = j;
    }
  }
  double a = ln_lo + std::max(0, best - 1) * grid_step;
  double b = ln_lo + std::min(points - 1, best + 1) * grid_step;
  const double inverse_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - inverse_phi * (b - a);
  double d = a + inverse_phi * (b - a);
  double fc = squares_at(c);
  double fd = squares_at(d);
  while (b - a > 1.0e-10) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - inverse_phi * (b - a);
      fc = squares_at(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + inverse_phi * (b - a);
      fd = squares_at(d);
    }
  }
  double ln_k = 0.5 * (a + b);
  // The grid point itself may beat the bracket's interior (a minimum at the range's end).
  if (best_squares < squares_at(ln_k))
    ln_k = ln_lo + best * grid_step;
  // k is not bounded by the data when an end of the range fits as well as the best k (to
  // round-off): a plateau reached before the second sample, or a curve still straight at the end.
  const double best_found = std::min(best_squares, squares_at(ln_k));
  const double tolerance = 1.0e-9 * best_found + 1.0e-14 * s.total_squares;
  result.at_search_limit =
      squares_at(ln_lo) <= best_found + tolerance || squares_at(ln_hi) <= best_found + tolerance;

  const double rate = std::exp(ln_k);
  const LinearFit fit = fit_at(times, values, s, model, rate, plateau_max);
  if (!fit.ok) {
    result.status = MixingFitStatus::flat;
    return result;
  }
  result.rate = rate;
  result.initial = fit.initial;
  result.plateau = fit.plateau;
  result.plateau_bounded = fit.bounded;
  result.r_squared = 1.0 - fit.squares / s.total_squares;
  result.rms = std::sqrt(fit.squares / s.count);
  result.status = MixingFitStatus::ok;
  return result;
}

}  // namespace partimix::analysis
