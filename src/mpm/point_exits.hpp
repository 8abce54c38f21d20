#pragma once
// Points that cross an exit plane leave the run (docs/mpm.md, "Exits and feeds"): the store is
// compacted, keeping the order of the points that stay, and their mass is counted.
#include <cstdint>
#include <vector>

#include "mpm/config.hpp"
#include "particles/particle_store.hpp"

namespace partimix::mpm {

// Removes the points beyond any of `exits` and returns their mass. `order` is scratch space
// kept by the caller (no allocation once it has grown to the point count).
double remove_exited(const std::vector<PointExit>& exits, ParticleStore& store,
                     std::vector<std::uint32_t>& order);

}  // namespace partimix::mpm
