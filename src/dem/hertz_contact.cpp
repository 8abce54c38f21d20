#include "dem/hertz_contact.hpp"

#include <cmath>

namespace partimix::dem {

NormalResponse HertzContact::respond(const PairProperties& pair, double overlap,
                                     double normal_velocity) const {
  const double contact_radius = std::sqrt(pair.radius * overlap);
  const double stiffness = 2.0 * pair.youngs_modulus * contact_radius;
  const double damping =
      2.0 * std::sqrt(5.0 / 6.0) * pair.damping * std::sqrt(pair.mass * stiffness);
  return {2.0 / 3.0 * stiffness * overlap - damping * normal_velocity, stiffness,
          8.0 * pair.shear_modulus * contact_radius, damping * pair.tangential_damping_scale};
}

}  // namespace partimix::dem
