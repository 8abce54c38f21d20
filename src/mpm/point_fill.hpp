#pragma once
// Material points laid on a lattice in the fill regions (docs/mpm.md, "Filling"): each point a
// share spacing^d of the bulk at the critical density, at rest or with the fill's velocity,
// stress-free or in geostatic equilibrium under gravity.
#include "core/vec.hpp"
#include "io/size_limits.hpp"
#include "mpm/config.hpp"
#include "mpm/point_fields.hpp"
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix::mpm {

// Appends the points of every fill of `config` to `store`. Throws InputError with the key path
// of the fill ("mpm.fill[i]...") when a region holds no lattice point or too many.
void fill_points(const MpmConfig& config, const Domain& domain, const Vec3& gravity,
                 const io::SizeLimits& limits, ParticleStore& store, PointFields& fields);

}  // namespace partimix::mpm
