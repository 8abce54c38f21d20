#pragma once
// The velocity profile of a circular Couette flow about the z axis, as the Taylor-Couette tests
// measure it: the RMS deviation of the fluid's tangential velocity from r omega(r).
#include <cmath>

#include "particles/particle_store.hpp"

namespace partimix {

template <class AngularVelocity>
double tangential_rms_error(const ParticleStore& store, AngularVelocity&& omega) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    const Vec3& x = store.position()[i];
    const double r = std::hypot(x.x(), x.y());
    const Vec3 tangent(-x.y() / r, x.x() / r, 0.0);
    const double error = store.velocity()[i].dot(tangent) - r * omega(r);
    sum += error * error;
    ++count;
  }
  return std::sqrt(sum / count);
}

}  // namespace partimix
