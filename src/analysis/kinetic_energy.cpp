#include "analysis/kinetic_energy.hpp"

#include <limits>

namespace partimix::analysis {

bool has_rotation_fields(const ParticleStore& particles) {
  return particles.find_scalar("radius") != nullptr &&
         particles.find_vector("angular_velocity") != nullptr;
}

KineticEnergy::KineticEnergy(const ParticleStore& particles)
    : rotational_(has_rotation_fields(particles)) {}

std::vector<Column> KineticEnergy::columns() const {
  if (rotational_)
    return {{"kinetic_energy", "J"}, {"rotational_energy", "J"}};
  return {{"kinetic_energy", "J"}};
}

void KineticEnergy::sample(const ParticleStore& particles, double /*time*/,
                           std::span<double> values) {
  double energy = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i)) {
      energy += 0.5 * particles.mass()[i] * particles.velocity()[i].squaredNorm();
    }
  }
  values[0] = energy;
  if (!rotational_)
    return;
  const Field<double>* radius = particles.find_scalar("radius");
  const Field<Vec3>* omega = particles.find_vector("angular_velocity");
  if (radius == nullptr || omega == nullptr) {
    values[1] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  // Grains with an angular momentum (superquadrics: the full inertia tensor) give w . L / 2;
  // solid spheres (2/5) m r^2 w^2 / 2.
  const Field<Vec3>* momentum = particles.find_vector("angular_momentum");
  double rotation = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const double r = radius->values[i];
    rotation += momentum ? 0.5 * omega->values[i].dot(momentum->values[i])
                         : 0.2 * particles.mass()[i] * r * r * omega->values[i].squaredNorm();
  }
  values[1] = rotation;
}

}  // namespace partimix::analysis
