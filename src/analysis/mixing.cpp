#include "analysis/mixing.hpp"

#include "analysis/mixing_rate.hpp"

namespace partimix::analysis {
namespace {

// The Lacey index of a random mixture: the fitted plateau is held at or below it
// (docs/mixing.md, "Mixing rate").
constexpr double kRandomMixtureLacey = 1.0;

}  // namespace

Mixing::Mixing(const MixingRegion& region)
    : cells_(make_sampling_cells(region)), min_count_(region.min_count), counts_(*cells_) {
  // The history grows by one entry per sample (not per step); this covers a usual run.
  constexpr std::size_t kExpectedSamples = 1024;
  times_.reserve(kExpectedSamples);
  laceys_.reserve(kExpectedSamples);
}

void Mixing::sample(const ParticleStore& particles, double time, std::span<double> values) {
  roles_.resize(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      roles_[i] = MixingRole::ignored;
    else
      roles_[i] = particles.tag()[i] == 1 ? MixingRole::tracer : MixingRole::other;
  }
  count_cells(*cells_, particles.position(), roles_, counts_);
  last_xi_ = uniformity_index(counts_);
  last_lacey_ = lacey_index(counts_, min_count_).index;
  values[0] = last_xi_;
  values[1] = last_lacey_;
  times_.push_back(time);
  laceys_.push_back(last_lacey_);
}

void Mixing::replay(double time, std::span<const double> values) {
  last_xi_ = values[0];
  last_lacey_ = values[1];
  times_.push_back(time);
  laceys_.push_back(last_lacey_);
}

void Mixing::add_figures(Figures& figures) const {
  figures.add("xi_final", last_xi_, "");
  figures.add("lacey_final", last_lacey_, "");
  for (const MixingModel model :
       {MixingModel::exponential, MixingModel::error_function, MixingModel::diffusive}) {
    const MixingRateFit fit = fit_mixing_rate(times_, laceys_, model, kRandomMixtureLacey);
    if (fit.status != MixingFitStatus::ok)
      continue;  // too few samples, or nothing to fit: no figures rather than NaN ones
    const std::string suffix = mixing_model_suffix(model);
    auto name = [&suffix](const char* stem) { return std::string(stem).append(suffix); };
    figures.add(name("lacey_rate_"), fit.rate, "1/s");
    figures.add(name("lacey_initial_"), fit.initial, "");
    figures.add(name("lacey_plateau_"), fit.plateau, "");
    figures.add(name("lacey_fit_r2_"), fit.r_squared, "");
    figures.add(name("lacey_fit_rms_"), fit.rms, "");
    figures.add(name("lacey_fit_at_limit_"), fit.at_search_limit ? 1.0 : 0.0, "");
    figures.add(name("lacey_plateau_bounded_"), fit.plateau_bounded ? 1.0 : 0.0, "");
  }
}

}  // namespace partimix::analysis
