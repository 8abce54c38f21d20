#pragma once
// A particle store in a checkpoint (DESIGN.md, "One run"): every field of the store, output or
// not, under <prefix>fields/<name>, and the particle count under <prefix>particles. Restoring
// gives back the same order and the same bits, so a method that restores its store and its own
// few numbers continues as if it had never stopped.
#include <string>

#include "core/state_archive.hpp"
#include "particles/particle_store.hpp"

namespace partimix {

void save_store(const ParticleStore& store, StateArchive& archive, const std::string& prefix);

// The store must have been built with the same fields (the same case): throws StateError when
// the particle count or the set of fields differs, naming what differs. A method whose points
// come and go (MPM's exits and feeds) passes `count_may_change`: the store takes the saved count,
// and its ids and kinds need not be those it was built with.
void restore_store(ParticleStore& store, const StateArchive& archive, const std::string& prefix,
                   bool count_may_change = false);

}  // namespace partimix
