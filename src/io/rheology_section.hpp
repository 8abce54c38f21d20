#pragma once
// The fluid's rheology in a case file (docs/case-reference.md, "fluid.rheology"): either the
// plain `fluid.viscosity: mu` of a Newtonian fluid or a `fluid.rheology` map naming a model
// (materials/rheology.hpp) with only the keys that model uses, its regularisation and its bounds.
#include "io/yaml_reader.hpp"
#include "materials/rheology.hpp"

namespace partimix::io {

// Reads `viscosity` or `rheology` (exactly one) from the `fluid` map.
materials::RheologyConfig read_fluid_rheology(Reader& fluid);

}  // namespace partimix::io
