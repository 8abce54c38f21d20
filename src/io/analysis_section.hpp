#pragma once
// The `analyses` list of a case file (docs/case-reference.md, "analyses"): each item names a
// measurement with only the keys it uses. Bodies are checked against the walls, power numbers
// against the body's motion and the fluid's rheology.
#include <vector>

#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

std::vector<AnalysisSpec> read_analyses(Reader& root, int dimensions,
                                        const std::vector<WallSpec>& walls, const FluidSpec& fluid);

}  // namespace partimix::io
