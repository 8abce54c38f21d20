#pragma once
// The stress update of a material point of a granular material over one step (docs/mpm.md,
// "Constitutive update"): pressure from the density (zero below the critical density: the
// disconnected state), the deviatoric stress by the Jaumann rate and Hooke's law, and the
// backward-Euler return to the mu(I) flow rule.
#include "core/vec.hpp"
#include "materials/granular/granular_material.hpp"

namespace partimix::materials {

struct GranularPoint {
  Mat3 stress = Mat3::Zero();   // Cauchy, tension positive [Pa]
  double pressure = 0.0;        // p = -tr(stress)/3 [Pa]
  double plastic_strain = 0.0;  // equivalent plastic shear strain gamma_p [-]
  double inertial_number = 0.0;
};

// The pressure of the material at `density`: K ln(rho / rho_c) at or above rho_c, else 0.
double granular_pressure(const GranularMaterial& material, double density);

// Updates `point` for the velocity gradient L over dt; `density` is the point's density at the
// end of the step.
void update_granular_stress(const GranularMaterial& material, const Mat3& velocity_gradient,
                            double dt, double density, GranularPoint& point);

}  // namespace partimix::materials
