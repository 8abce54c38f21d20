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

// 100 sd(phi) / mean(phi) over the slices with enough material (docs/truck-drum.md), the
// variance in two passes (one pass loses its digits to cancellation for a uniform mixture).
double variation_percent(const std::vector<double>& coarse, const std::vector<double>& all) {
  double total = 0.0;
  for (double v : all)
    total += v;
  const double least = kLeastShareOfMean * total / static_cast<double>(all.size());
  const auto counted = [&](std::size_t k) { return all[k] > least; };
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (counted(k)) {
      sum += coarse[k] / all[k];
      ++count;
    }
  if (count < 2 || !(sum > 0.0))
    return 0.0;
  const double mean = sum / count;
  double squares = 0.0;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (counted(k))
      squares += std::pow(coarse[k] / all[k] - mean, 2);
  return 100.0 * std::sqrt(squares / count) / mean;
}

}  // namespace

DrumSegregation::DrumSegregation(const DrumMeasures& options)
    : options_(options),
      coarse_(static_cast<std::size_t>(std::max(options.bins, 0)), 0.0),
      all_(coarse_.size(), 0.0) {
  if (!options.drum || options.bins < 2)
    throw std::invalid_argument("drum_segregation: needs a truck drum and at least 2 bins");
}

void DrumSegregation::sample(const ParticleStore& particles, double time,
                             std::span<double> values) {
  const GrainVolumes volume(particles, "drum_segregation");
  const Field<std::int32_t>& species = grain_species(particles, "drum_segregation");
  std::fill(coarse_.begin(), coarse_.end(), 0.0);
  std::fill(all_.begin(), all_.end(), 0.0);
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
    if (species.values[i] == options_.coarse_species)
      coarse_[k] += volume(i);
  }
  double coarse = 0.0;
  double all = 0.0;
  for (std::size_t k = 0; k < all_.size(); ++k) {
    coarse += coarse_[k];
    all += all_[k];
  }
  values[0] = variation_percent(coarse_, all_);
  values[1] = all > 0.0 ? coarse / all : 0.0;
  record(time, values[0]);
}

void DrumSegregation::replay(double time, std::span<const double> values) {
  record(time, values[0]);
}

void DrumSegregation::record(double time, double degree) {
  if (time > options_.mixing_until && recorded_)
    return;
  recorded_ = true;
  degree_ = degree;
}

void DrumSegregation::add_figures(Figures& figures) const {
  if (!recorded_)
    return;
  figures.add("segregation_degree", degree_, "%");
  figures.add("segregation_within_threshold", degree_ <= options_.threshold ? 1.0 : 0.0, "");
}

}  // namespace partimix::analysis
