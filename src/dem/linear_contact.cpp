#include "dem/linear_contact.hpp"

#include <cmath>

namespace partimix::dem {

NormalResponse LinearContact::respond(const PairProperties& pair, double overlap,
                                      double normal_velocity) const {
  const double damping = 2.0 * pair.damping * std::sqrt(pair.mass * stiffness_);
  const double tangential_stiffness = 2.0 / 7.0 * stiffness_;
  return {stiffness_ * overlap - damping * normal_velocity, stiffness_, tangential_stiffness,
          2.0 * std::sqrt(5.0 / 6.0) * pair.damping * std::sqrt(pair.mass * tangential_stiffness)};
}

}  // namespace partimix::dem
