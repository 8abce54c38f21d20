#include "analysis/grain_volumes.hpp"

#include <numbers>

#include "core/error.hpp"

namespace partimix::analysis {

GrainVolumes::GrainVolumes(const ParticleStore& particles, const std::string& analysis, bool flat)
    : volume_(flat ? nullptr : particles.find_scalar("volume")),
      radius_(particles.find_scalar("radius")),
      flat_(flat) {
  if (radius_ == nullptr && volume_ == nullptr) {
    throw RunError("the analysis " + analysis +
                   " needs the particle field 'radius' (DEM grains); these particles have none");
  }
}

double GrainVolumes::operator()(std::size_t i) const {
  if (volume_ != nullptr)
    return volume_->values[i];
  const double r = radius_->values[i];
  return flat_ ? std::numbers::pi * r * r : (4.0 / 3.0) * std::numbers::pi * r * r * r;
}

const Field<std::int32_t>& grain_species(const ParticleStore& particles,
                                         const std::string& analysis) {
  const Field<std::int32_t>* species = particles.find_integer("species");
  if (species == nullptr)
    throw RunError("the analysis " + analysis + " needs the particle field 'species' (DEM grains)");
  return *species;
}

}  // namespace partimix::analysis
