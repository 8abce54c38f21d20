#pragma once
// Mixing rate (docs/mixing.md, "Mixing rate"): least-squares fits of a sampled mixing index M(t)
// (the Lacey index) to a model that starts at M_0 and approaches a plateau M_f,
//
//   M(t) = M_0 + (M_f - M_0) h(k (t - t_0)),
//
// with t_0 the time of the first valid sample and
//   exponential:     h(x) = 1 - exp(-x)     (first-order kinetics, Lacey 1954)
//   error function:  h(x) = erf(x)          (seed 002, eq. 11: G(R_m t), G the error integral)
//   diffusive:       h(x) = erf(sqrt(x))    (M - M_0 grows like sqrt(t) at first, as when two
//                                            layers mix by diffusion across their interface)
//
// For a given rate k the model is linear in M_0 and M_f, so these follow by linear least squares
// (variable projection); the residual is then minimised over log k by a scan of a log grid and a
// golden-section search about the best grid point. No allocation: two passes over the samples
// per trial k (the sums, then the residuals).
#include <limits>
#include <span>
#include <string>

namespace partimix::analysis {

enum class MixingModel { exponential, error_function, diffusive };

// Why a fit has no numbers, if it has none.
enum class MixingFitStatus {
  ok,
  too_few_samples,  // fewer than kMinMixingFitSamples samples with finite time and value
  no_time_spread,   // all valid samples at one time
  flat,             // every valid value the same: no rate to find
};

inline constexpr int kMinMixingFitSamples = 4;

struct MixingRateFit {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  MixingFitStatus status = MixingFitStatus::too_few_samples;
  double rate = nan;             // k [1/s]
  double initial = nan;          // M_0: the model at t_0
  double plateau = nan;          // M_f: the model as t -> infinity
  double r_squared = nan;        // 1 - SS_res / SS_tot about the mean of the samples
  double rms = nan;              // sqrt(SS_res / n)
  double start_time = nan;       // t_0 [s]: the time of the first valid sample
  int samples = 0;               // n: the valid samples used
  bool at_search_limit = false;  // an end of the searched range fits as well: k not determined
  bool plateau_bounded = false;  // M_f held at the bound plateau_max: no plateau in the data
};

// h(x) of the model, x = k (t - t_0) >= 0: 0 at x = 0, -> 1 as x -> infinity.
double mixing_approach(MixingModel model, double x);

// The model's value at time t for the fitted parameters (NaN when the fit has none).
double mixing_model_value(MixingModel model, const MixingRateFit& fit, double time);

// Fits M(t) to `model`. Samples whose time or value is not finite are skipped; fewer than
// kMinMixingFitSamples valid samples, or valid samples that all share one time, give a NaN fit
// with the status saying why. Rates are searched over
//   k in [1e-3 / T, 50 / tau_1],
// T the span of the valid times and tau_1 the smallest positive t - t_0: below, the model is
// indistinguishable from a straight line (exponential, erf) or a square root (diffusive) in t;
// above, it has reached its plateau at every sample but the first. When an end of this range
// fits as well as the best k (to round-off), the data do not bound k and at_search_limit is set.
// M_f is bounded above by plateau_max (1 for a Lacey index, the value of a random mixture): for a
// k whose free fit puts M_f above it, M_f is held at plateau_max and M_0 fitted alone, and the
// fit says so (plateau_bounded). Throws std::invalid_argument when the spans differ in length.
MixingRateFit fit_mixing_rate(std::span<const double> times, std::span<const double> values,
                              MixingModel model,
                              double plateau_max = std::numeric_limits<double>::infinity());

// "exp", "erf" or "diffusive", for figure names.
std::string mixing_model_suffix(MixingModel model);

}  // namespace partimix::analysis
