#include "analysis/drum_segregation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/grain_volumes.hpp"

namespace partimix::analysis {
namespace {

// Slices with less material than this share of the mean slice's are left out of the degree: the
// head's tip and the opening hold a few grains whose share would swing wildly.
constexpr double kLeastShareOfMean = 0.05;

// The slices counted: those with more than kLeastShareOfMean of the mean slice's material.
void count_slices(const std::vector<double>& all, std::vector<std::size_t>& counted) {
  double total = 0.0;
  for (double v : all)
    total += v;
  const double least = kLeastShareOfMean * total / static_cast<double>(all.size());
  counted.clear();
  for (std::size_t k = 0; k < all.size(); ++k)
    if (all[k] > least)
      counted.push_back(k);
}

// 100 sd(phi) / mean(phi) over the counted slices (docs/truck-drum.md), the variance in two
// passes (one pass loses its digits to cancellation for a uniform mixture).
double variation_percent(const std::vector<double>& coarse, const std::vector<double>& all,
                         const std::vector<std::size_t>& counted) {
  double sum = 0.0;
  for (const std::size_t k : counted)
    sum += coarse[k] / all[k];
  if (counted.size() < 2 || !(sum > 0.0))
    return 0.0;
  const auto m = static_cast<double>(counted.size());
  const double mean = sum / m;
  double squares = 0.0;
  for (const std::size_t k : counted)
    squares += std::pow(coarse[k] / all[k] - mean, 2);
  return 100.0 * std::sqrt(squares / m) / mean;
}

// S_r = 100 sqrt((m - 1) / m² Σ_k P (1 - P) / n_k) / P over the m counted slices: S_r² is the
// expected S² for grains put in the slices at random, each coarse with probability P (the coarse
// share of the counted slices' material), n_k = (Σ v)² / Σ v² slice k's effective number of
// grains (its count for equal grains; docs/truck-drum.md, "Segregation degree").
double random_mixture_percent(const std::vector<double>& coarse, const std::vector<double>& all,
                              const std::vector<double>& squares,
                              const std::vector<std::size_t>& counted) {
  double coarse_total = 0.0;
  double total = 0.0;
  for (const std::size_t k : counted) {
    coarse_total += coarse[k];
    total += all[k];
  }
  if (counted.size() < 2 || !(coarse_total > 0.0))
    return 0.0;
  const double p = coarse_total / total;
  double inverse_counts = 0.0;
  for (const std::size_t k : counted)
    inverse_counts += squares[k] / (all[k] * all[k]);
  const auto m = static_cast<double>(counted.size());
  return 100.0 * std::sqrt((m - 1.0) / (m * m) * p * (1.0 - p) * inverse_counts) / p;
}

}  // namespace

DrumSegregation::DrumSegregation(const DrumMeasures& options)
    : options_(options),
      coarse_(static_cast<std::size_t>(std::max(options.bins, 0)), 0.0),
      all_(coarse_.size(), 0.0),
      squares_(coarse_.size(), 0.0) {
  counted_.reserve(coarse_.size());
  if (!options.drum || options.bins < 2)
    throw std::invalid_argument("drum_segregation: needs a truck drum and at least 2 bins");
}

void DrumSegregation::sample(const ParticleStore& particles, double time,
                             std::span<double> values) {
  const GrainVolumes volume(particles, "drum_segregation");
  const Field<std::int32_t>& species = grain_species(particles, "drum_segregation");
  std::fill(coarse_.begin(), coarse_.end(), 0.0);
  std::fill(all_.begin(), all_.end(), 0.0);
  std::fill(squares_.begin(), squares_.end(), 0.0);
  const double length = options_.drum->drum().length();
  const auto bins = static_cast<double>(all_.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const DrumPlace place = drum_place(*options_.drum, particles.position()[i]);
    if (!place.inside)
      continue;
    const auto k = static_cast<std::size_t>(std::clamp(place.z / length * bins, 0.0, bins - 1.0));
    all_[k] += volume(i);
    squares_[k] += volume(i) * volume(i);
    if (species.values[i] == options_.coarse_species)
      coarse_[k] += volume(i);
  }
  double coarse = 0.0;
  double all = 0.0;
  for (std::size_t k = 0; k < all_.size(); ++k) {
    coarse += coarse_[k];
    all += all_[k];
  }
  count_slices(all_, counted_);
  values[0] = variation_percent(coarse_, all_, counted_);
  values[1] = all > 0.0 ? coarse / all : 0.0;
  values[2] = random_mixture_percent(coarse_, all_, squares_, counted_);
  record(time, values[0], values[2]);
}

void DrumSegregation::replay(double time, std::span<const double> values) {
  record(time, values[0], values[2]);
}

void DrumSegregation::record(double time, double degree, double random) {
  if (time > options_.mixing_until && recorded_)
    return;
  recorded_ = true;
  degree_ = degree;
  random_ = random;
  if (time >= options_.average_from) {
    averaged_sum_ += degree;
    ++averaged_;
  }
}

void DrumSegregation::add_figures(Figures& figures) const {
  if (!recorded_)
    return;
  figures.add("segregation_degree", degree_, "%");
  figures.add("segregation_random", random_, "%");
  if (averaged_ > 0)
    figures.add("segregation_mean", averaged_sum_ / averaged_, "%");
  figures.add("segregation_within_threshold", degree_ <= options_.threshold ? 1.0 : 0.0, "");
}

}  // namespace partimix::analysis
