#include "dem/pair_properties.hpp"

#include <cmath>
#include <numbers>

namespace partimix::dem {

double damping_factor(double restitution) {
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

namespace {

// 1 / E* and 1 / G* contributions of one side (docs/dem.md, "Effective quantities").
double normal_compliance(const Material& m) {
  return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
}

double shear_compliance(const Material& m) {
  return 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.youngs_modulus;
}

}  // namespace

PairProperties pair_properties(const ContactSide& a, const ContactSide& b, double restitution) {
  PairProperties pair;
  pair.radius = 1.0 / (1.0 / a.radius + 1.0 / b.radius);
  pair.mass = 1.0 / (1.0 / a.mass + 1.0 / b.mass);
  pair.youngs_modulus = 1.0 / (normal_compliance(a.material) + normal_compliance(b.material));
  pair.shear_modulus = 1.0 / (shear_compliance(a.material) + shear_compliance(b.material));
  pair.damping = damping_factor(restitution);
  return pair;
}

}  // namespace partimix::dem
