#include "dem/hertz_contact.hpp"

#include <cmath>

namespace partimix::dem {

double HertzContact::force(const PairProperties& pair, double overlap,
                           double normal_velocity) const {
  const double k_hertz = 4.0 / 3.0 * pair.youngs_modulus * std::sqrt(pair.radius);
  const double root = std::sqrt(overlap);
  const double damping = std::sqrt(5.0) * pair.damping * std::sqrt(pair.mass * k_hertz);
  return k_hertz * overlap * root - damping * std::sqrt(root) * normal_velocity;
}

double HertzContact::normal_stiffness(const PairProperties& pair, double overlap) const {
  return 2.0 * pair.youngs_modulus * std::sqrt(pair.radius * overlap);
}

double HertzContact::tangential_stiffness(const PairProperties& pair, double overlap) const {
  return 8.0 * pair.shear_modulus * std::sqrt(pair.radius * overlap);
}

}  // namespace partimix::dem
