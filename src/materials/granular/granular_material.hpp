#pragma once
// A dense granular material as a continuum (docs/mpm.md, "Constitutive update"): Hookean
// elasticity with E and nu, the mu(I) friction law of Jop, Forterre & Pouliquen (2006), and
// the critical (apparent) density below which the grains lose contact (Dunatunga & Kamrin 2015).
#include <cmath>
#include <string>

namespace partimix::materials {

struct GranularMaterial {
  std::string name;
  double density = 2200.0;        // rho_c: bulk density at critical packing [kg/m^3]
  double packing_fraction = 0.6;  // phi_c: grain density rho_s = rho_c / phi_c
  double youngs_modulus = 1.0e7;  // E [Pa]
  double poisson_ratio = 0.3;     // nu
  double grain_diameter = 0.005;  // d [m]
  double mu_s = 0.404;            // friction at I -> 0
  double mu_2 = 0.64;             // friction at I -> infinity
  double i0 = 0.28;               // I0

  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  double grain_density() const { return density / packing_fraction; }
  // P-wave speed sqrt((K + 4G/3) / rho_c) [m/s] (docs/mpm.md, "Time step").
  double wave_speed() const {
    return std::sqrt((bulk_modulus() + 4.0 * shear_modulus() / 3.0) / density);
  }
  // mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1), written so that I = 0 gives mu_s.
  double friction(double inertial_number) const {
    return mu_s + (mu_2 - mu_s) * inertial_number / (i0 + inertial_number);
  }
  // I = gamma_dot d / sqrt(p / rho_s).
  double inertial_number(double shear_rate, double pressure) const {
    return shear_rate * grain_diameter / std::sqrt(pressure / grain_density());
  }
};

}  // namespace partimix::materials
