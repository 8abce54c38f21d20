#include "dem/tangential_contact.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::dem {

double seed_spring_cap(const PairProperties& pair, double friction, double overlap) {
  return friction * pair.youngs_modulus / (4.0 * pair.shear_modulus) * overlap;
}

namespace {

// R(n_old -> n) xi: the normal part removed and the old length restored (Luding 2008). Squared
// lengths until one square root is needed (this runs for every contact of every step).
void carry_into_plane(Vec3& spring, const Vec3& normal) {
  const double length2 = spring.squaredNorm();
  if (length2 == 0.0)
    return;
  spring -= spring.dot(normal) * normal;
  const double in_plane2 = spring.squaredNorm();
  spring = in_plane2 > 0.0 ? Vec3(spring * std::sqrt(length2 / in_plane2)) : Vec3::Zero();
}

void limit_length(Vec3& spring, double cap) {
  const double length2 = spring.squaredNorm();
  if (length2 > cap * cap)
    spring *= cap / std::sqrt(length2);
}

}  // namespace

Vec3 tangential_force(const TangentialStep& step, Vec3& spring) {
  carry_into_plane(spring, step.normal);
  spring += step.tangential_velocity * step.dt;
  limit_length(spring, step.spring_cap);
  const Vec3 trial = -step.stiffness * spring - step.damping * step.tangential_velocity;
  const double coulomb = step.friction * std::max(step.normal_force, 0.0);
  const double size2 = trial.squaredNorm();
  if (size2 <= coulomb * coulomb)
    return trial;
  const Vec3 sliding = trial * (coulomb / std::sqrt(size2));
  spring = -sliding / step.stiffness;
  return sliding;
}

}  // namespace partimix::dem
