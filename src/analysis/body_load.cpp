#include "analysis/body_load.hpp"

#include <Eigen/Geometry>

#include "core/error.hpp"

namespace partimix::analysis {

BodyLoad measure_body_load(const ParticleStore& particles, int body, const Vec3& own_axis_point,
                           const Vec3& vessel_axis_point) {
  const auto* bodies = particles.find_integer("body");
  const auto* forces = particles.find_vector("body_force");
  const auto* couples = particles.find_vector("body_couple");
  if (bodies == nullptr || forces == nullptr || couples == nullptr)
    throw RunError("body loads need the particle fields 'body', 'body_force' and 'body_couple'");
  BodyLoad load;
  for (std::size_t j = 0; j < particles.size(); ++j) {
    if (bodies->values[j] != body)
      continue;
    const Vec3& f = forces->values[j];
    const Vec3& x = particles.position()[j];
    load.force += f;
    const Vec3& c = couples->values[j];
    load.torque_own += (x - own_axis_point).cross(f) + c;
    load.torque_vessel += (x - vessel_axis_point).cross(f) + c;
  }
  return load;
}

}  // namespace partimix::analysis
