#pragma once
// The domain and configuration of a 2D multi-material SPH solver built in a test
// (docs/multi-material-sph.md, "The scheme"): the plane z = 0 from (x_lo, y_lo) to (x_hi, y_hi),
// and sph.scheme multi_material at a spacing with its materials.
#include <utility>
#include <vector>

#include "particles/domain.hpp"
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

}  // namespace partimix::test_support
