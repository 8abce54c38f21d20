#pragma once
// The fluid's rheology in a case file (docs/case-reference.md, "fluid.rheology"): either the
// plain `fluid.viscosity: mu` of a Newtonian fluid or a `fluid.rheology` map naming a model
// (sph/rheology.hpp) with only the keys that model uses, its regularisation and its bounds.
#include "io/yaml_reader.hpp"
#include "sph/rheology.hpp"

namespace partimix::io {

// Reads `viscosity` or `rheology` (exactly one) from the `fluid` map.
sph::RheologyConfig read_fluid_rheology(Reader& fluid);

}  // namespace partimix::io
