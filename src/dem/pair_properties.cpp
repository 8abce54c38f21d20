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

MaterialPair material_pair(const Material& a, const Material& b, double restitution) {
  const double youngs_modulus = 1.0 / (normal_compliance(a) + normal_compliance(b));
  const double shear_modulus = 1.0 / (shear_compliance(a) + shear_compliance(b));
  return {youngs_modulus, shear_modulus, damping_factor(restitution),
          std::sqrt(4.0 * shear_modulus / youngs_modulus)};
}

PairProperties pair_properties(const MaterialPair& materials, double radius_a, double radius_b,
                               double mass_a, double mass_b) {
  return {1.0 / (1.0 / radius_a + 1.0 / radius_b),
          1.0 / (1.0 / mass_a + 1.0 / mass_b),
          materials.youngs_modulus,
          materials.shear_modulus,
          materials.damping,
          materials.tangential_damping_scale};
}

PairProperties grain_pair_properties(const MaterialPair& materials, double radius_a,
                                     double radius_b, double mass_a, double mass_b) {
  return {radius_a * radius_b / (radius_a + radius_b),
          mass_a * mass_b / (mass_a + mass_b),
          materials.youngs_modulus,
          materials.shear_modulus,
          materials.damping,
          materials.tangential_damping_scale};
}

PairProperties pair_properties(const ContactSide& a, const ContactSide& b, double restitution) {
  return pair_properties(material_pair(a.material, b.material, restitution), a.radius, b.radius,
                         a.mass, b.mass);
}

}  // namespace partimix::dem
