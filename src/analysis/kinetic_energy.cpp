#include "analysis/kinetic_energy.hpp"

namespace partimix::analysis {

void KineticEnergy::sample(const ParticleStore& particles, double /*time*/,
                           std::span<double> values) {
  double energy = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i)) {
      energy += 0.5 * particles.mass()[i] * particles.velocity()[i].squaredNorm();
    }
  }
  values[0] = energy;
}

}  // namespace partimix::analysis
