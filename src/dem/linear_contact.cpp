#include "dem/linear_contact.hpp"

#include <cmath>

namespace partimix::dem {

double LinearContact::force(const PairProperties& pair, double overlap,
                            double normal_velocity) const {
  const double damping = 2.0 * pair.damping * std::sqrt(pair.mass * stiffness_);
  return stiffness_ * overlap - damping * normal_velocity;
}

}  // namespace partimix::dem
