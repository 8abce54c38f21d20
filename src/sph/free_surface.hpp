#pragma once
// Whether the fluid of a case has a free surface at t = 0: a fluid particle that has no
// neighbour (fluid or wall) along one of the axis directions, i.e. none at 0.5 to 2 spacings
// ahead along +x, -x, +y, -y (and +z, -z in 3D). A gap narrower than that (the clearance around
// a thin body) is no surface. Without gravity nothing holds such a surface in weakly-compressible
// SPH (the pressure there is the background one and the particles drift or are flung out by a
// stirrer), so a case with one and no gravity gets a warning (docs/sph.md, "Free surfaces").
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix::sph {

bool has_free_surface(const ParticleStore& store, const Domain& domain, double spacing);

}  // namespace partimix::sph
