#include "analysis/drum_discharge.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/grain_volumes.hpp"
#include "analysis/mass_in_region.hpp"

namespace partimix::analysis {
namespace {

constexpr double kSecondsPerMinute = 60.0;

}  // namespace

DrumDischarge::DrumDischarge(const DrumMeasures& options) : options_(options) {
  if (!options.drum)
    throw std::invalid_argument("drum_discharge: needs a truck drum");
  if (!(options.fit_from < options.fit_until))
    throw std::invalid_argument("drum_discharge: fit_until must be later than fit_from");
}

void DrumDischarge::sample(const ParticleStore& particles, double time, std::span<double> values) {
  const GrainVolumes volume(particles, "drum_discharge");
  const Field<std::int32_t>* species = particles.find_integer("species");
  const geometry::TruckDrumGeometry& drum = options_.drum->drum();
  const double length = drum.length();
  const double stream_end = length + 2.0 * drum.parameters().opening_radius;
  double inside = 0.0;
  double stream = 0.0;
  double coarse = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const DrumPlace place = drum_place(*options_.drum, particles.position()[i]);
    const double v = volume(i);
    if (place.inside) {
      inside += v;
    } else if (place.z > length && place.z <= stream_end) {
      stream += v;
      if (species != nullptr && species->values[i] == options_.coarse_species)
        coarse += v;
    }
  }
  const double first = sampled_ ? first_volume_ : inside;
  values[0] = inside;
  values[1] = first - inside;
  values[2] = sampled_ && time > last_time_
                  ? kSecondsPerMinute * (last_volume_ - inside) / (time - last_time_)
                  : 0.0;
  values[3] = stream;
  values[4] = stream > 0.0 ? coarse / stream : 0.0;
  record(time, values);
}

void DrumDischarge::replay(double time, std::span<const double> values) {
  record(time, values);
}

void DrumDischarge::record(double time, std::span<const double> values) {
  if (!sampled_)
    first_volume_ = values[0];
  sampled_ = true;
  last_time_ = time;
  last_volume_ = values[0];
  if (time >= options_.fit_from && time <= options_.fit_until)
    fit_.add(time, values[1]);
  stream_.push_back({values[1], values[3], values[3] * values[4]});
}

double DrumDischarge::stream_share(double from, double to) const {
  const double end = first_volume_ - last_volume_;
  double volume = 0.0;
  double coarse = 0.0;
  for (const StreamSample& s : stream_) {
    if (s.discharged >= from * end && s.discharged <= to * end) {
      volume += s.volume;
      coarse += s.coarse;
    }
  }
  return volume > 0.0 ? coarse / volume : std::numeric_limits<double>::quiet_NaN();
}

void DrumDischarge::add_figures(Figures& figures) const {
  if (!sampled_)
    return;
  if (first_volume_ > 0.0)
    figures.add("residual_rate", 100.0 * last_volume_ / first_volume_, "%");
  const double slope = fit_.slope();
  if (fit_.count() >= kMinDischargeSamples && std::isfinite(slope))
    figures.add("discharge_rate", kSecondsPerMinute * slope, "m^3/min");
  const double a = stream_share(0.2, 0.3);
  const double b = stream_share(0.7, 0.8);
  if (std::isfinite(a) && std::isfinite(b) && a + b > 0.0)
    figures.add("coarse_aggregate_difference", 100.0 * std::abs(a - b) / (0.5 * (a + b)), "%");
}

void DrumDischarge::add_caveats(Caveats& caveats) const {
  if (fit_.count() < kMinDischargeSamples)
    caveats["discharge_rate"] = fmt::format(
        "left out: {} sample(s) at fit_from <= t <= fit_until, and the least-squares line needs "
        "at least {}",
        fit_.count(), kMinDischargeSamples);
  if (!std::isfinite(stream_share(0.2, 0.3)) || !std::isfinite(stream_share(0.7, 0.8)))
    caveats["coarse_aggregate_difference"] =
        "left out: no material passed the opening while 20-30% or 70-80% of the discharged "
        "volume had left; sample more often";
}

}  // namespace partimix::analysis
