#pragma once
// The case keys of the multi-material SPH scheme (docs/case-reference.md, "sph.materials" and
// "sph.multi_material"): the list of materials, each an equation of state with only that model's
// keys, an initial state, thermal properties and optionally an elastic-plastic solid; the
// scheme's own settings; and the material each fluid region names.
#include <vector>

#include "io/yaml_reader.hpp"
#include "sph/multi_material/material_spec.hpp"

namespace partimix::sph {

// Reads `materials` (required) and `multi_material` (optional) from the `sph` map.
MultiMaterialSettings read_multi_material(io::Reader& sph);

// Reads a fluid region's required `material`, one of the names of `materials`; its index there.
int read_region_material(io::Reader& region, const std::vector<MaterialSpec>& materials);

}  // namespace partimix::sph
