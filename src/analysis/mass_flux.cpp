#include "analysis/mass_flux.hpp"

#include <cmath>
#include <stdexcept>

namespace partimix::analysis {

MassFlux::MassFlux(const FluxPlane& plane) : plane_(plane) {
  if (!(plane.width > 0.0) || !(std::abs(plane.normal.norm() - 1.0) < 1e-9))
    throw std::invalid_argument("mass_flux: width must be positive and the normal a unit vector");
}

void MassFlux::sample(const ParticleStore& particles, double time, std::span<double> values) {
  double flux = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const double distance = (particles.position()[i] - plane_.point).dot(plane_.normal);
    if (std::abs(distance) < 0.5 * plane_.width)
      flux += particles.mass()[i] * particles.velocity()[i].dot(plane_.normal);
  }
  values[0] = flux / plane_.width;
  record(time, values[0]);
}

void MassFlux::replay(double time, std::span<const double> values) {
  record(time, values[0]);
}

void MassFlux::record(double time, double flux) {
  if (time >= plane_.average_from) {
    sum_ += flux;
    ++count_;
  }
}

void MassFlux::add_figures(Figures& figures) const {
  if (count_ > 0)
    figures.add("mean_mass_flux", sum_ / count_, "kg/s");
}

}  // namespace partimix::analysis
