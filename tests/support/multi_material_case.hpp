#pragma once
// Case texts of the multi-material SPH scheme for the case-reading tests (docs/case-reference.md,
// "sph.materials").
#include <string>

namespace partimix::test_support {

// A region of the fluid section with the keys `extra` (lines indented as the region's keys).
inline std::string region_with(const std::string& extra) {
  return "  regions:\n    - shape: box\n      min: [0, 0]\n      max: [0.5, 0.5]\n" + extra;
}

// A 2D case with scheme: multi_material, the items `materials` of sph.materials and the fluid
// section's keys `fluid` (by default one region of `liquid`).
inline std::string multi_material_case(
    const std::string& materials,
    const std::string& fluid = region_with("      material: liquid\n")) {
  return R"(solver: sph
dimensions: 2
domain:
  min: [0, 0]
  max: [1.0, 1.0]
time:
  end: 1.0e-3
  output_interval: 1.0e-4
sph:
  spacing: 0.01
  scheme: multi_material
  materials:
)" + materials +
         "fluid:\n" + fluid;
}

}  // namespace partimix::test_support
