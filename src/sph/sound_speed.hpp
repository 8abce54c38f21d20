#pragma once
// The numerical speed of sound c0 (docs/sph.md, "Equation of state"): given, or
// mach_factor * U_max with U_max given or estimated as 2 sqrt(|g| H) for fluid of height H
// (the front speed of a dam break of depth H, Ritter 1892), so that the Mach number stays
// <= 0.1 and density varies by about 1% (Monaghan 1994). With mach_factor 10 this is
// c0 = 20 sqrt(g H), the DualSPHysics default.
#include "particles/particle_store.hpp"
#include "sph/config.hpp"

namespace partimix::sph {

// Height of the fluid along `gravity`: from the lowest to the highest fluid particle plus one
// spacing (each particle stands for a cell of size dp). 0 when gravity is zero.
double fluid_height(const ParticleStore& store, const Vec3& gravity, double spacing);

// Throws InputError naming sph.max_velocity when no estimate is possible.
double resolve_sound_speed(const Config& config, const ParticleStore& store,
                           const Vec3& hydrostatic_gravity);

}  // namespace partimix::sph
