#pragma once
// The keys of the truck drum's analyses, drum_segregation and drum_discharge
// (docs/case-reference.md, "analyses"; docs/truck-drum.md, "Measurements").
#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

// `wall` (a truck_drum that is fixed or turns about its own axis), `coarse_species`, and the
// type's own: `bins`, `threshold`, `mixing_until`, `average_from`, or `fit_from`, `fit_until`.
void read_drum_measures(Reader& item, AnalysisSpec& analysis, const Case& the_case);

}  // namespace partimix::io
