#include "dem/time_step.hpp"

#include <cmath>
#include <numbers>

namespace partimix::dem {

double rayleigh_time(double radius, double density, const Material& material) {
  const double shear_modulus = material.youngs_modulus / (2.0 * (1.0 + material.poisson_ratio));
  return std::numbers::pi * radius * std::sqrt(density / shear_modulus) /
         (0.1631 * material.poisson_ratio + 0.8766);
}

double linear_contact_time(double mass, double stiffness) {
  return std::numbers::pi * std::sqrt(0.5 * mass / stiffness);
}

}  // namespace partimix::dem
