#pragma once
// Particles on concentric rings about the z axis (a polar lattice), for the tests of flows
// between cylinders: both walls are then smooth.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "particles/particle_store.hpp"

namespace partimix {

// `count` rings of particles `spacing` apart, the first at radius `first`, going outward
// (step +1) or inward (step -1); each ring holds round(2 pi r / dp) particles.
inline void add_rings(ParticleStore& store, double spacing, double first, int count, int step,
                      ParticleKind kind) {
  for (int k = 0; k < count; ++k) {
    const double r = first + step * k * spacing;
    const int n = static_cast<int>(std::lround(2.0 * std::numbers::pi * r / spacing));
    const double offset = 0.5 * (k % 2);
    for (int a = 0; a < n; ++a) {
      const double angle = 2.0 * std::numbers::pi * (a + offset) / n;
      const std::size_t i = store.size();
      store.resize(i + 1);
      store.position()[i] = Vec3(r * std::cos(angle), r * std::sin(angle), 0.0);
      store.kind()[i] = static_cast<std::int32_t>(kind);
      store.id()[i] = static_cast<std::int64_t>(i);
    }
  }
}

}  // namespace partimix
