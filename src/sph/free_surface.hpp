#pragma once
// Whether the fluid of a case has a free surface at t = 0: a fluid particle with markedly fewer
// neighbours (fluid or wall, within the kernel support) than a particle deep in the fluid has.
// Without gravity nothing holds such a surface in weakly-compressible SPH (the pressure there
// is the background one and the particles drift or are flung out by a stirrer), so a case with
// one and no gravity gets a warning (docs/sph.md, "Free surfaces").
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix::sph {

// True when some fluid particle has fewer than 3/4 of the largest neighbour count of any fluid
// particle within `support`.
bool has_free_surface(const ParticleStore& store, const Domain& domain, double support);

}  // namespace partimix::sph
