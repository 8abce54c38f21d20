// Mixing-rate fits (docs/mixing.md, "Mixing rate"): M(t) = M_0 + (M_f - M_0) h(k (t - t_0)) with
// h(x) = 1 - exp(-x), erf(x) or erf(sqrt(x)). Synthetic curves of known k, M_0 and M_f are
// recovered to round-off without noise, and within four standard errors of the least-squares
// estimate (worked out from the Jacobian at the true parameters) with a fixed uniform noise; the
// other models fit the same data worse (lower R^2); NaN samples are skipped; too few samples or a
// flat curve give NaN with a status.
#include "analysis/mixing_rate.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/uniform_random.hpp"

namespace partimix::analysis {
namespace {

using test_support::Uniform;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

struct Truth {
  MixingModel model;
  double rate;
  double initial;
  double plateau;
  double start = 0.0;
};

struct Series {
  std::vector<double> times;
  std::vector<double> values;
};

double truth_at(const Truth& truth, double t) {
  return truth.initial + (truth.plateau - truth.initial) *
                             mixing_approach(truth.model, truth.rate * (t - truth.start));
}

// 101 samples every 0.1 s from truth.start; with noise uniform in [-amplitude, amplitude].
Series synthetic(const Truth& truth, double amplitude = 0.0, std::uint64_t seed = 7) {
  Uniform uniform(seed);
  Series s;
  for (int i = 0; i <= 100; ++i) {
    const double t = truth.start + 0.1 * i;
    s.times.push_back(t);
    s.values.push_back(truth_at(truth, t) + amplitude * (2.0 * uniform() - 1.0));
  }
  return s;
}

MixingRateFit fit(const Series& s, MixingModel model) {
  return fit_mixing_rate(s.times, s.values, model);
}

// Standard error of k for noise of standard deviation sigma: sigma sqrt([(J^T J)^-1]_kk), J the
// Jacobian of the model in (M_0, M_f, k) at the true parameters.
double rate_standard_error(const Truth& truth, const Series& s, double sigma) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  for (const double t : s.times) {
    const double tau = t - truth.start;
    const double x = truth.rate * tau;
    const double h = mixing_approach(truth.model, x);
    // dh/dk = tau h'(x): exp: tau e^-x; erf(x): tau (2/sqrt pi) e^(-x^2);
    // erf(sqrt(x)): tau e^-x / sqrt(pi x) = sqrt(tau/(pi k)) e^-x.
    const double pi = std::numbers::pi;
    double dh_dk = std::sqrt(tau / (pi * truth.rate)) * std::exp(-x);
    if (truth.model == MixingModel::exponential)
      dh_dk = tau * std::exp(-x);
    if (truth.model == MixingModel::error_function)
      dh_dk = tau * 2.0 / std::sqrt(pi) * std::exp(-x * x);
    const Eigen::Vector3d j(1.0 - h, h, (truth.plateau - truth.initial) * dh_dk);
    normal += j * j.transpose();
  }
  return sigma * std::sqrt(normal.inverse()(2, 2));
}

const Truth kExponential{MixingModel::exponential, 0.8, 0.05, 0.92};
const Truth kErf{MixingModel::error_function, 0.5, -0.02, 0.95};
const Truth kDiffusive{MixingModel::diffusive, 0.5, 0.1, 0.97};
const MixingModel kModels[] = {MixingModel::exponential, MixingModel::error_function,
                               MixingModel::diffusive};

TEST(MixingRate, ApproachFunctions) {
  EXPECT_DOUBLE_EQ(mixing_approach(MixingModel::exponential, 0.0), 0.0);
  EXPECT_NEAR(mixing_approach(MixingModel::exponential, 1.0), 1.0 - std::exp(-1.0), 1e-15);
  EXPECT_DOUBLE_EQ(mixing_approach(MixingModel::error_function, 0.0), 0.0);
  EXPECT_NEAR(mixing_approach(MixingModel::error_function, 0.5), std::erf(0.5), 1e-15);
  EXPECT_NEAR(mixing_approach(MixingModel::error_function, 2.0), std::erf(2.0), 1e-15);
  EXPECT_DOUBLE_EQ(mixing_approach(MixingModel::diffusive, 0.0), 0.0);
  EXPECT_NEAR(mixing_approach(MixingModel::diffusive, 1.0), std::erf(1.0), 1e-15);
  EXPECT_NEAR(mixing_approach(MixingModel::diffusive, 4.0), std::erf(2.0), 1e-15);
  EXPECT_EQ(mixing_model_suffix(MixingModel::exponential), "exp");
  EXPECT_EQ(mixing_model_suffix(MixingModel::error_function), "erf");
  EXPECT_EQ(mixing_model_suffix(MixingModel::diffusive), "diffusive");
}

TEST(MixingRate, ExponentialWithoutNoiseIsRecoveredToRoundOff) {
  const MixingRateFit result = fit(synthetic(kExponential), MixingModel::exponential);
  ASSERT_EQ(result.status, MixingFitStatus::ok);
  EXPECT_EQ(result.samples, 101);
  EXPECT_NEAR(result.rate, 0.8, 1e-6 * 0.8);
  EXPECT_NEAR(result.initial, 0.05, 1e-7);
  EXPECT_NEAR(result.plateau, 0.92, 1e-7);
  EXPECT_GT(result.r_squared, 1.0 - 1e-12);
  EXPECT_LT(result.rms, 1e-7);
  EXPECT_DOUBLE_EQ(result.start_time, 0.0);
  EXPECT_FALSE(result.at_search_limit);
}

TEST(MixingRate, ErrorFunctionsWithoutNoiseAreRecoveredToRoundOff) {
  for (const Truth& truth : {kErf, kDiffusive}) {
    const MixingRateFit result = fit(synthetic(truth), truth.model);
    ASSERT_EQ(result.status, MixingFitStatus::ok);
    const std::string model = mixing_model_suffix(truth.model);
    EXPECT_NEAR(result.rate, 0.5, 1e-6 * 0.5) << model;
    EXPECT_NEAR(result.initial, truth.initial, 1e-7) << model;
    EXPECT_NEAR(result.plateau, truth.plateau, 1e-7) << model;
    EXPECT_GT(result.r_squared, 1.0 - 1e-12) << model;
    EXPECT_LT(result.rms, 1e-7) << model;
    EXPECT_FALSE(result.at_search_limit) << model;
  }
}

TEST(MixingRate, TimeOriginIsTheFirstSample) {
  // The same curve sampled from t = 3 s: k and M_0 (the value at t = 3 s) are the same.
  Truth shifted = kExponential;
  shifted.start = 3.0;
  const MixingRateFit result = fit(synthetic(shifted), MixingModel::exponential);
  ASSERT_EQ(result.status, MixingFitStatus::ok);
  EXPECT_DOUBLE_EQ(result.start_time, 3.0);
  EXPECT_NEAR(result.rate, 0.8, 1e-6 * 0.8);
  EXPECT_NEAR(result.initial, 0.05, 1e-7);
  EXPECT_NEAR(mixing_model_value(MixingModel::exponential, result, 4.0), truth_at(shifted, 4.0),
              1e-7);
  EXPECT_TRUE(std::isnan(mixing_model_value(MixingModel::exponential, result, 2.0)));
}

TEST(MixingRate, FallingCurveGivesAPositiveRate) {
  // M falling from 0.9 to 0.1 (segregation): k > 0 with M_f < M_0.
  const Truth falling{MixingModel::exponential, 1.5, 0.9, 0.1};
  const MixingRateFit result = fit(synthetic(falling), MixingModel::exponential);
  EXPECT_NEAR(result.rate, 1.5, 1e-6 * 1.5);
  EXPECT_NEAR(result.plateau, 0.1, 1e-7);
}

// With noise uniform in [-0.01, 0.01] (sigma = 0.01/sqrt 3, about 0.7% of the rise) the
// estimate of k must lie within 4 standard errors of the truth (the standard error is about 1%
// of k here); R^2 stays above 0.999 and the RMS residual near sigma.
TEST(MixingRate, NoisyCurvesAreRecoveredWithinFourStandardErrors) {
  constexpr double kAmplitude = 0.01;
  const double sigma = kAmplitude / std::sqrt(3.0);
  for (const Truth& truth : {kExponential, kErf, kDiffusive}) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      const Series s = synthetic(truth, kAmplitude, seed);
      const MixingRateFit result = fit(s, truth.model);
      ASSERT_EQ(result.status, MixingFitStatus::ok);
      const double se = rate_standard_error(truth, s, sigma);
      EXPECT_LT(se, 0.02 * truth.rate) << mixing_model_suffix(truth.model);
      EXPECT_NEAR(result.rate, truth.rate, 4.0 * se)
          << mixing_model_suffix(truth.model) << " seed " << seed;
      EXPECT_NEAR(result.plateau, truth.plateau, 4.0 * kAmplitude);
      EXPECT_GT(result.r_squared, 0.995);
      EXPECT_NEAR(result.rms, sigma, 0.3 * sigma);
    }
  }
}

TEST(MixingRate, TheWrongModelsFitWorse) {
  // Data of each model: the other two models' R^2 is lower by more than 0.005 (they reach 0.958
  // to 0.993 without noise, against 1; 0.999 with the noise) and their RMS residual is more than
  // twice as large.
  for (const double amplitude : {0.0, 0.01}) {
    for (const Truth& truth : {kExponential, kErf, kDiffusive}) {
      const Series data = synthetic(truth, amplitude);
      const MixingRateFit right = fit(data, truth.model);
      for (const MixingModel model : kModels) {
        if (model == truth.model)
          continue;
        const MixingRateFit wrong = fit(data, model);
        EXPECT_LT(wrong.r_squared, right.r_squared - 0.005)
            << mixing_model_suffix(model) << " on " << mixing_model_suffix(truth.model) << " data, "
            << amplitude;
        EXPECT_GT(wrong.rms, 2.0 * right.rms)
            << mixing_model_suffix(model) << " on " << mixing_model_suffix(truth.model) << " data, "
            << amplitude;
      }
    }
  }
}

TEST(MixingRate, AxialDiffusionOfTwoHalvesIsFitBestByTheDiffusiveModel) {
  // Two halves of a bed of length L mixing by diffusion (D) along it, sampled in thin slices
  // (docs/mixing.md, "Mixing rate"): 1 - M = (8/pi^2) sum_{n odd} n^-2 exp(-2 n^2 pi^2 D t/L^2).
  // Over D t / L^2 in [0, 0.1] (M from 0 to 0.97) the diffusive model fits it to R^2 = 0.9993,
  // the exponential to 0.9951, the seed's erf to 0.9875.
  Series s;
  for (int i = 0; i <= 100; ++i) {
    const double tau = 0.001 * i;  // D t / L^2
    double sum = 0.0;
    for (int n = 1; n < 4000; n += 2)
      sum += std::exp(-2.0 * n * n * std::numbers::pi * std::numbers::pi * tau) / (1.0 * n * n);
    s.times.push_back(tau);
    s.values.push_back(1.0 - 8.0 / (std::numbers::pi * std::numbers::pi) * sum);
  }
  const MixingRateFit diffusive = fit(s, MixingModel::diffusive);
  const MixingRateFit exponential = fit(s, MixingModel::exponential);
  const MixingRateFit erf = fit(s, MixingModel::error_function);
  EXPECT_GT(diffusive.r_squared, 0.999);
  EXPECT_GT(diffusive.r_squared, exponential.r_squared + 0.003);
  EXPECT_GT(exponential.r_squared, erf.r_squared + 0.005);
}

TEST(MixingRate, NanSamplesAreSkipped) {
  const Series clean = synthetic(kExponential);
  Series holed;
  for (std::size_t i = 0; i < clean.times.size(); ++i) {
    holed.times.push_back(clean.times[i]);
    holed.values.push_back(i % 7 == 3 ? kNan : clean.values[i]);
    if (i % 10 == 5) {
      holed.times.push_back(kNan);
      holed.values.push_back(0.5);
    }
  }
  // A leading NaN (as a Lacey index before any tracer enters the region).
  holed.times.insert(holed.times.begin(), -1.0);
  holed.values.insert(holed.values.begin(), kNan);
  const MixingRateFit result = fit(holed, MixingModel::exponential);
  ASSERT_EQ(result.status, MixingFitStatus::ok);
  EXPECT_EQ(result.samples, 101 - 14);  // i = 3, 10, ..., 94 dropped
  EXPECT_DOUBLE_EQ(result.start_time, 0.0);
  EXPECT_NEAR(result.rate, 0.8, 1e-6 * 0.8);
  EXPECT_NEAR(result.plateau, 0.92, 1e-7);
}

TEST(MixingRate, FewerThanFourValidSamplesGiveNan) {
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> values{0.0, 0.5, kNan, 0.7, 0.75};
  const MixingRateFit four = fit_mixing_rate(times, values, MixingModel::exponential);
  EXPECT_EQ(four.status, MixingFitStatus::ok);
  EXPECT_EQ(four.samples, 4);
  const std::vector<double> three_values{0.0, kNan, kNan, 0.7, 0.75};
  for (const MixingModel model : kModels) {
    const MixingRateFit three = fit_mixing_rate(times, three_values, model);
    EXPECT_EQ(three.status, MixingFitStatus::too_few_samples);
    EXPECT_EQ(three.samples, 3);
    EXPECT_TRUE(std::isnan(three.rate));
    EXPECT_TRUE(std::isnan(three.initial));
    EXPECT_TRUE(std::isnan(three.plateau));
    EXPECT_TRUE(std::isnan(three.r_squared));
    EXPECT_TRUE(std::isnan(three.rms));
  }
  const MixingRateFit none = fit_mixing_rate({}, {}, MixingModel::exponential);
  EXPECT_EQ(none.status, MixingFitStatus::too_few_samples);
}

TEST(MixingRate, FlatCurveAndOneTimeGiveNan) {
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0};
  const MixingRateFit flat =
      fit_mixing_rate(times, std::vector<double>{0.4, 0.4, 0.4, 0.4}, MixingModel::exponential);
  EXPECT_EQ(flat.status, MixingFitStatus::flat);
  EXPECT_TRUE(std::isnan(flat.rate));
  EXPECT_TRUE(std::isnan(flat.r_squared));
  const MixingRateFit one_time =
      fit_mixing_rate(std::vector<double>{1.0, 1.0, 1.0, 1.0},
                      std::vector<double>{0.1, 0.2, 0.3, 0.4}, MixingModel::exponential);
  EXPECT_EQ(one_time.status, MixingFitStatus::no_time_spread);
  EXPECT_TRUE(std::isnan(one_time.rate));
}

TEST(MixingRate, StepBeyondTheSampleSpacingHitsTheSearchLimit) {
  // M jumps to its plateau before the second sample: any k >= 50 / tau_1 fits; the fit says so.
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> values{0.0, 1.0, 1.0, 1.0, 1.0};
  const MixingRateFit result = fit_mixing_rate(times, values, MixingModel::exponential);
  EXPECT_EQ(result.status, MixingFitStatus::ok);
  EXPECT_TRUE(result.at_search_limit);
  EXPECT_GE(result.rate, 20.0);
  EXPECT_NEAR(result.plateau, 1.0, 1e-9);
  EXPECT_NEAR(result.r_squared, 1.0, 1e-9);
}

// A curve whose free fit has its plateau below the bound is fitted as without it.
TEST(MixingRate, BoundAbovePlateauChangesNothing) {
  for (const Truth& truth : {kExponential, kErf, kDiffusive}) {
    const Series s = synthetic(truth, 0.01);
    const MixingRateFit free = fit(s, truth.model);
    const MixingRateFit bounded = fit_mixing_rate(s.times, s.values, truth.model, 1.0);
    const std::string model = mixing_model_suffix(truth.model);
    EXPECT_FALSE(bounded.plateau_bounded) << model;
    EXPECT_DOUBLE_EQ(bounded.rate, free.rate) << model;
    EXPECT_DOUBLE_EQ(bounded.plateau, free.plateau) << model;
  }
}

// SS_res of M = M_0 + (M_f - M_0) h(k t) over a series.
double squares(const Series& s, MixingModel model, double rate, double initial, double plateau) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.times.size(); ++i) {
    const Truth trial{model, rate, initial, plateau, s.times.front()};
    const double r = s.values[i] - truth_at(trial, s.times[i]);
    sum += r * r;
  }
  return sum;
}

// A run that ends far below its plateau (here the early part of a curve that would level off at
// 1.6): the free fit puts M_f above 1; with the bound 1 the plateau is held there, flagged, and
// (k, M_0) minimise SS_res among curves with M_f = 1: any step of 1e-3 in k or M_0 does worse.
TEST(MixingRate, PlateauAboveTheBoundIsHeldThere) {
  const Truth rising{MixingModel::exponential, 0.15, 0.02, 1.6};
  const Series s = synthetic(rising, 0.01);
  ASSERT_GT(fit(s, MixingModel::exponential).plateau, 1.0);
  const MixingRateFit result = fit_mixing_rate(s.times, s.values, MixingModel::exponential, 1.0);
  ASSERT_EQ(result.status, MixingFitStatus::ok);
  EXPECT_TRUE(result.plateau_bounded);
  EXPECT_DOUBLE_EQ(result.plateau, 1.0);
  EXPECT_FALSE(result.at_search_limit);
  const double best =
      squares(s, MixingModel::exponential, result.rate, result.initial, result.plateau);
  EXPECT_NEAR(result.rms, std::sqrt(best / 101.0), 1e-12);
  for (const double step : {-1e-3, 1e-3}) {
    EXPECT_GT(squares(s, MixingModel::exponential, result.rate * (1.0 + step), result.initial, 1.0),
              best);
    EXPECT_GT(squares(s, MixingModel::exponential, result.rate, result.initial + step, 1.0), best);
  }
}

TEST(MixingRate, SpansOfDifferentLengthAreRefused) {
  EXPECT_THROW(fit_mixing_rate(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0},
                               MixingModel::exponential),
               std::invalid_argument);
}

}  // namespace
}  // namespace partimix::analysis
