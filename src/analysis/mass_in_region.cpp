#include "analysis/mass_in_region.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace partimix::analysis {

MassInRegion::MassInRegion(const MassRegion& region) : region_(region) {
  if (!(region.hi.x() > region.lo.x()) || !(region.hi.y() > region.lo.y()) ||
      !(region.hi.z() >= region.lo.z()))
    throw std::invalid_argument("mass_in_region: the box needs max > min along x and y");
  if (!(region.fit_from < region.fit_until))
    throw std::invalid_argument("mass_in_region: fit_until must be later than fit_from");
}

double MassInRegion::mass_inside(const ParticleStore& particles) const {
  double mass = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const Vec3& x = particles.position()[i];
    if ((x.array() >= region_.lo.array()).all() && (x.array() <= region_.hi.array()).all())
      mass += particles.mass()[i];
  }
  return mass;
}

void MassInRegion::sample(const ParticleStore& particles, double time, std::span<double> values) {
  const double mass = mass_inside(particles);
  values[0] = mass;
  values[1] = sampled_ && time > last_time_ ? (last_mass_ - mass) / (time - last_time_) : 0.0;
  record(time, mass);
}

void MassInRegion::replay(double time, std::span<const double> values) {
  record(time, values[0]);
}

void MassInRegion::record(double time, double mass) {
  if (time >= region_.fit_from && time <= region_.fit_until)
    fit_.add(time, mass);
  sampled_ = true;
  last_time_ = time;
  last_mass_ = mass;
}

void MassInRegion::add_figures(Figures& figures) const {
  if (sampled_)
    figures.add("mass_final", last_mass_, "kg");
  const double slope = fit_.slope();
  if (fit_.count() >= kMinDischargeSamples && std::isfinite(slope))
    figures.add("discharge_rate", -slope, "kg/s");
}

void MassInRegion::add_caveats(Caveats& caveats) const {
  if (fit_.count() >= kMinDischargeSamples)
    return;
  caveats["discharge_rate"] = fmt::format(
      "left out: {} sample(s) at fit_from <= t <= fit_until (t = {:.4g} to {:.4g} s), and the "
      "least-squares line needs at least {}; sample more often or widen the window",
      fit_.count(), region_.fit_from, region_.fit_until, kMinDischargeSamples);
}

}  // namespace partimix::analysis
