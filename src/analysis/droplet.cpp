#include "analysis/droplet.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace partimix::analysis {
namespace {

enum ColumnIndex : std::size_t {
  kDiameter,
  kDiameterRatio,
  kPressure,
  kDamageMax,
  kGasTemperature,
  kRuptured
};

// The volume-weighted centroid of the droplet's particles.
Vec3 centroid_of(const ParticleStore& particles, const DropletFields& fields) {
  Vec3 weighted = Vec3::Zero();
  double volume = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    volume += fields.volume(i);
    weighted += fields.volume(i) * particles.position()[i];
  }
  return volume > 0.0 ? Vec3(weighted / volume) : weighted;
}

// The largest damage of the shell's particles; NaN without any.
double damage_max(const ParticleStore& particles, const DropletFields& fields, int shell) {
  double largest = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i) && fields.material[i] == shell)
      largest = std::fmax(largest, fields.damage[i]);
  }
  return largest;
}

// The mass-weighted mean temperature of the particles of the materials `gas` [K].
double gas_temperature(const ParticleStore& particles, const DropletFields& fields,
                       const std::vector<int>& gas) {
  WeightedMean mean;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i) && std::ranges::find(gas, fields.material[i]) != gas.end())
      mean.add(fields.temperature[i], fields.mass[i]);
  }
  return mean.value();
}

}  // namespace

Droplet::Droplet(const DropletOptions& options)
    : options_(options), rupture_test_(options.link), ring_test_(options.link) {
  if (options.shell < 0)
    throw std::invalid_argument("droplet: needs the shell's material");
  if (!(options.link > 0.0))
    throw std::invalid_argument("droplet: the link distance must be > 0");
  if (!(options.after_rupture > 0.0))
    throw std::invalid_argument("droplet: after_rupture must be > 0");
  if (options.dimensions != 2 && options.dimensions != 3)
    throw std::invalid_argument("droplet: dimensions must be 2 or 3");
}

std::vector<Column> Droplet::columns() const {
  return {{"diameter", "m"},  {"diameter_ratio", ""},   {"pressure_above_ambient", "Pa"},
          {"damage_max", ""}, {"gas_temperature", "K"}, {"ruptured", ""}};
}

void Droplet::sample(const ParticleStore& particles, double time, std::span<double> values) {
  const DropletFields fields(particles);
  const Vec3 centre = centroid_of(particles, fields);
  if (!labelled_)
    label_surfaces(particles, fields, centre, time);
  collect_shell(particles, fields);
  const double diameter = outline_diameter(centre);
  values[kDiameter] = diameter;
  values[kDiameterRatio] = diameter / (sampled_ ? first_diameter_ : diameter);
  values[kPressure] = pressure_inside(particles, fields);
  values[kDamageMax] = damage_max(particles, fields, options_.shell);
  values[kGasTemperature] = gas_temperature(particles, fields, options_.gas);
  values[kRuptured] = ruptured(centre) ? 1.0 : 0.0;
  record(time, values);
}

void Droplet::replay(double time, std::span<const double> values) {
  record(time, values);
}

bool Droplet::is_shell(const ParticleStore& particles, const DropletFields& fields,
                       std::size_t i) const {
  return particles.is_material(i) && fields.material[i] == options_.shell;
}

void Droplet::label_surfaces(const ParticleStore& particles, const DropletFields& fields,
                             const Vec3& centre, double time) {
  std::vector<std::int64_t> ids;
  std::vector<double> distance;
  std::vector<double> spacing;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!is_shell(particles, fields, i))
      continue;
    ids.push_back(particles.id()[i]);
    distance.push_back((particles.position()[i] - centre).norm());
    spacing.push_back(spacing_equivalent(fields.volume(i), options_.dimensions));
  }
  const std::vector<ShellSurface> surface = shell_surfaces(distance, spacing);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (surface[k] != ShellSurface::none)
      surface_of_[ids[k]] = surface[k];
  }
  labelled_ = true;
  labelled_on_resume_ = sampled_;
  labelled_at_ = time;
}

void Droplet::collect_shell(const ParticleStore& particles, const DropletFields& fields) {
  shell_position_.clear();
  shell_damage_.clear();
  shell_surface_.clear();
  shell_volume_ = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!is_shell(particles, fields, i))
      continue;
    const auto labelled = surface_of_.find(particles.id()[i]);
    shell_position_.push_back(particles.position()[i]);
    shell_damage_.push_back(fields.damage[i]);
    shell_surface_.push_back(labelled == surface_of_.end() ? ShellSurface::none : labelled->second);
    shell_volume_ += fields.volume(i);
  }
}

// The mean distances of the shell's inner and outer surface particles from the centre give its
// outline (outline_diameter); a shell of one layer, all inner, has both at the inner's.
double Droplet::outline_diameter(const Vec3& centre) const {
  WeightedMean inner;
  WeightedMean outer;
  for (std::size_t k = 0; k < shell_position_.size(); ++k) {
    const double distance = (shell_position_[k] - centre).norm();
    if (shell_surface_[k] == ShellSurface::inner)
      inner.add(distance, 1.0);
    else if (shell_surface_[k] == ShellSurface::outer)
      outer.add(distance, 1.0);
  }
  const double outer_distance = std::isnan(outer.value()) ? inner.value() : outer.value();
  return analysis::outline_diameter(inner.value(), outer_distance, shell_volume_,
                                    options_.dimensions);
}

// The volume-weighted median pressure of the particles that are not of the shell [Pa].
double Droplet::pressure_inside(const ParticleStore& particles, const DropletFields& fields) {
  inside_pressure_.clear();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i) && fields.material[i] != options_.shell)
      inside_pressure_.emplace_back(fields.pressure[i], fields.volume(i));
  }
  return weighted_median(inside_pressure_);
}

bool Droplet::ruptured(const Vec3& centre) {
  if (rupture_test_.ruptured(shell_position_, shell_damage_, shell_surface_))
    return true;
  if (options_.dimensions != 2)
    return false;
  const bool closes = ring_test_.closes(shell_position_, shell_damage_, centre);
  if (!ring_checked_) {
    ring_checked_ = true;
    ring_closed_ = closes;
  }
  return ring_closed_ && !closes;
}

void Droplet::record(double time, std::span<const double> values) {
  if (!sampled_)
    first_diameter_ = values[kDiameter];
  sampled_ = true;
  last_time_ = time;
  ratio_max_ = std::fmax(ratio_max_, values[kDiameterRatio]);
  if (!rupture_ && values[kRuptured] == 1.0) {
    rupture_ = Rupture{time, values[kPressure]};
    after_rupture_.emplace(time + options_.after_rupture);
  }
  if (after_rupture_)
    after_rupture_->add(time, values[kPressure]);
}

void Droplet::add_figures(Figures& figures) const {
  if (std::isfinite(ratio_max_))
    figures.add("diameter_ratio_max", ratio_max_, "");
  if (!rupture_)
    return;
  figures.add("rupture_time", rupture_->time, "s");
  if (std::isfinite(rupture_->pressure))
    figures.add("pressure_at_rupture", rupture_->pressure, "Pa");
  if (after_rupture_->reached() && std::isfinite(after_rupture_->value()))
    figures.add("pressure_after_rupture", after_rupture_->value(), "Pa");
}

std::optional<std::string> Droplet::rupture_caveat() const {
  if (labelled_on_resume_ && !(rupture_ && rupture_->time < labelled_at_)) {
    return fmt::format(
        "the shell's surfaces were labelled at t = {:.4g} s, the first sample after the run "
        "resumed, not at the run's first sample (a checkpoint does not keep them)",
        labelled_at_);
  }
  if (sampled_ && !rupture_) {
    return fmt::format("left out: the shell had not ruptured by the last sample (t = {:.4g} s)",
                       last_time_);
  }
  return std::nullopt;
}

void Droplet::add_caveats(Caveats& caveats) const {
  if (const std::optional<std::string> reason = rupture_caveat())
    caveats["rupture_time"] = *reason;
  if (after_rupture_ && !after_rupture_->reached()) {
    caveats["pressure_after_rupture"] = fmt::format(
        "left out: the last sample (t = {:.4g} s) comes before rupture_time + {:g} s = {:.4g} s",
        last_time_, options_.after_rupture, after_rupture_->target());
  }
}

}  // namespace partimix::analysis
