#pragma once
// The particle fields of the multi-material SPH scheme that the droplet analysis reads
// (docs/multi-material-sph.md, "The scheme"; docs/case-reference.md, "analyses", droplet).
#include <cstdint>
#include <vector>

#include "particles/particle_store.hpp"

namespace partimix::analysis {

struct DropletFields {
  // Throws RunError when the particles lack one of the fields (a method of another scheme).
  explicit DropletFields(const ParticleStore& particles);

  // m / rho of particle i [m^d].
  double volume(std::size_t i) const { return mass[i] / density[i]; }

  const std::vector<double>& mass;            // [kg]
  const std::vector<std::int32_t>& material;  // the index in sph.materials
  const std::vector<double>& density;         // [kg/m^3]
  const std::vector<double>& pressure;        // above the ambient [Pa]
  const std::vector<double>& temperature;     // [K]
  const std::vector<double>& damage;          // [-]
};

}  // namespace partimix::analysis
