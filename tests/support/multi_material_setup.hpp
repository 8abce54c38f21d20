#pragma once
// The domain and configuration of a 2D multi-material SPH solver built in a test
// (docs/multi-material-sph.md, "The scheme"): the plane z = 0 from (x_lo, y_lo) to (x_hi, y_hi),
// and sph.scheme multi_material at a spacing with its materials; a square block of one material.
#include <cstdint>
#include <utility>
#include <vector>

#include "particles/domain.hpp"
#include "particles/particle_store.hpp"
#include "sph/config.hpp"
#include "sph/multi_material/material_spec.hpp"

namespace partimix::test_support {

inline Domain plane_domain(double x_lo, double y_lo, double x_hi, double y_hi) {
  Domain domain;
  domain.dimensions = 2;
  domain.lo = Vec3(x_lo, y_lo, 0.0);
  domain.hi = Vec3(x_hi, y_hi, 0.0);
  return domain;
}

inline sph::Config multi_material_config(double spacing, std::vector<sph::MaterialSpec> materials) {
  sph::Config config;
  config.scheme = "multi_material";
  config.spacing = spacing;
  config.multi_material.materials = std::move(materials);
  return config;
}

// A side x side block of particles of material 0 at rest, laid on a square lattice at spacing from
// the origin (particle centres at (i + 1/2, j + 1/2) spacing, row by row), of the given density.
inline void square_block(ParticleStore& store, int side, double spacing, double density) {
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const std::size_t n = store.size();
      store.resize(n + 1);
      store.position()[n] = Vec3(i + 0.5, j + 0.5, 0.0) * spacing;
      store.mass()[n] = density * spacing * spacing;
      store.id()[n] = static_cast<std::int64_t>(n);
    }
  store.add_integer("material", "");
}

}  // namespace partimix::test_support
