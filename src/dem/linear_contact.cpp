#include "dem/linear_contact.hpp"

#include <cmath>

namespace partimix::dem {

NormalResponse LinearContact::respond(const PairProperties& pair, double overlap,
                                      double normal_velocity) const {
  const double damping = 2.0 * pair.damping * std::sqrt(pair.mass * stiffness_);
  return {stiffness_ * overlap - damping * normal_velocity, stiffness_, 2.0 / 7.0 * stiffness_};
}

}  // namespace partimix::dem
