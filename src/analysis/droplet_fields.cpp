#include "analysis/droplet_fields.hpp"

#include "core/error.hpp"

namespace partimix::analysis {
namespace {

template <class Field>
const Field& required(const Field* field) {
  if (field == nullptr) {
    throw RunError(
        "the analysis droplet needs the particle fields material, density, pressure, "
        "temperature and damage (sph.scheme: multi_material); these particles lack one");
  }
  return *field;
}

}  // namespace

DropletFields::DropletFields(const ParticleStore& particles)
    : mass(particles.mass()),
      material(required(particles.find_integer("material")).values),
      density(required(particles.find_scalar("density")).values),
      pressure(required(particles.find_scalar("pressure")).values),
      temperature(required(particles.find_scalar("temperature")).values),
      damage(required(particles.find_scalar("damage")).values) {}

}  // namespace partimix::analysis
