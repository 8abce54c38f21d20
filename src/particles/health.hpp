#pragma once
// The checks that stop a run that has gone wrong: a non-finite value in any field, or a
// particle outside the domain on a non-periodic axis.
#include <optional>
#include <string>

#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix {

// A description naming the first bad particle (its id, field and position), or nothing.
std::optional<std::string> find_bad_particle(const ParticleStore& store, const Domain& domain);

}  // namespace partimix
