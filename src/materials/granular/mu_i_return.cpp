#include "materials/granular/mu_i_return.hpp"

#include <cmath>

namespace partimix::materials {

// xi x^2 + (xi a + b - S) x - S a = 0 with S = tau_trial - mu_s p, xi = G dt,
// a = I0 sqrt(p / rho_s) / d, b = (mu_2 - mu_s) p; each form of the root avoids cancellation.
double plastic_shear_rate(const GranularMaterial& material, double tau_trial, double pressure,
                          double shear_dt) {
  const double excess = tau_trial - material.mu_s * pressure;
  if (!(excess > 0.0) || !(pressure > 0.0))
    return 0.0;
  const double a =
      material.i0 * std::sqrt(pressure / material.grain_density()) / material.grain_diameter;
  const double b = (material.mu_2 - material.mu_s) * pressure;
  const double linear = shear_dt * a + b - excess;
  const double root = std::sqrt(linear * linear + 4.0 * shear_dt * excess * a);
  if (linear > 0.0)
    return 2.0 * excess * a / (root + linear);
  return (root - linear) / (2.0 * shear_dt);
}

}  // namespace partimix::materials
