#pragma once
// A linear elastic solid of the multi-material SPH scheme for the validation tests
// (docs/multi-material-sph.md, "Solid"): the pressure c0^2 (rho - rho0) (Tait with gamma = 1,
// c0^2 = K / rho0) and Hooke's law with shear modulus G, never yielding.
#include <cmath>
#include <limits>
#include <string>

#include "sph/multi_material/material_spec.hpp"

namespace partimix::test_support {

inline sph::MaterialSpec elastic_solid(const std::string& name, double density, double bulk_modulus,
                                       double shear_modulus, double artificial_stress) {
  sph::MaterialSpec spec;
  spec.name = name;
  spec.eos.model = "tait";
  spec.eos.reference_density = density;
  spec.eos.sound_speed = std::sqrt(bulk_modulus / density);
  spec.eos.gamma = 1.0;
  spec.specific_heat = 1000.0;
  sph::SolidSpec solid;
  solid.shear_modulus = shear_modulus;
  solid.johnson_cook.A = std::numeric_limits<double>::infinity();
  solid.johnson_cook.melt_temperature = std::numeric_limits<double>::infinity();
  solid.artificial_stress = artificial_stress;
  spec.solid = solid;
  return spec;
}

}  // namespace partimix::test_support
