#pragma once
// One step of an elastic-plastic SPH particle (docs/multi-material-sph.md, "Solid"): the
// deviatoric stress advanced by Hooke's law in the Jaumann rate, returned to the Johnson-Cook
// yield surface scaled by (1 - D) (the seed's eq. 11), the plastic strain accumulated, the
// plastic work turned into heat, and the damage grown by the seed's eq. 12 towards the failure
// strain of eq. 13 at the stress triaxiality sigma_m / sigma_eq = -p / sigma_eq.
#include "core/vec.hpp"
#include "sph/multi_material/material_spec.hpp"

namespace partimix::sph {

struct SolidPoint {
  Mat3 deviatoric_stress = Mat3::Zero();  // S [Pa]
  double plastic_strain = 0.0;            // r [-]
  double damage = 0.0;                    // D in [0, 1]
};

struct SolidStepResult {
  double plastic_strain_increment = 0.0;  // dr [-]
  double plastic_work = 0.0;              // sigma_y dr / rho [J/kg]
};

// Advances `point` by dt from the elastic trial stress `trial` (S after the Jaumann update) at
// gauge pressure p [Pa], temperature T [K] and density rho [kg/m^3].
SolidStepResult return_to_yield(const SolidSpec& solid, const Mat3& trial, double pressure,
                                double temperature, double density, double dt, SolidPoint& point);

}  // namespace partimix::sph
