#pragma once
// The backward-Euler return of the mu(I) flow rule (docs/mpm.md, "mu(I) flow rule"; Dunatunga &
// Kamrin 2015, eq. 4.12): the plastic shear rate gamma_dot_p that satisfies
// tau_trial - G dt gamma_dot_p = mu(I(gamma_dot_p)) p, the positive root of a quadratic.
#include "materials/granular/granular_material.hpp"

namespace partimix::materials {

// gamma_dot_p [1/s] for a trial shear stress tau_trial > mu_s p, pressure p > 0 and
// shear_dt = G dt [Pa s]; 0 when the trial stress is within the yield surface.
double plastic_shear_rate(const GranularMaterial& material, double tau_trial, double pressure,
                          double shear_dt);

}  // namespace partimix::materials
