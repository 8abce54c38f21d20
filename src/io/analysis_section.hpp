#pragma once
// The `analyses` list of a case file (docs/case-reference.md, "analyses"): each item names a
// measurement of one method's particles with only the keys it uses. Bodies are checked against
// the walls, power numbers against the body's motion and the method's fluid.
#include <vector>

#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

// Reads `analyses` after the rest of `the_case`: each analysis measures one of its methods.
std::vector<AnalysisSpec> read_analyses(Reader& root, const Case& the_case);

}  // namespace partimix::io
