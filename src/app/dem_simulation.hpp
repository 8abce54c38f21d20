#pragma once
// A DEM simulation built from a case (docs/dem.md, "Filling"): grains inserted at random into
// the fill region, settled under gravity with the walls held still, split into two species by
// the fill's plane; then the walls' motions start at t = 0.
#include "app/simulation.hpp"

namespace partimix::app {

Simulation build_dem_simulation(const io::Case& the_case);

}  // namespace partimix::app
