#pragma once
// The numerical speed of sound c0 (docs/sph.md, "Speed of sound"): given, or the largest of the
// three criteria of Morris, Fox & Zhu (1997, "Modeling low Reynolds number incompressible
// flows using SPH", the choice of the speed of sound), with the density variation
// delta = 1 / mach_factor^2 they allow:
//   inertia   c0 >= mach_factor * U_max,
//   viscosity c0 >= mach_factor * sqrt(nu U_max / L),
//   gravity   c0 >= mach_factor * sqrt(|g| H),
// U_max given or estimated as 2 sqrt(|g| H) for fluid of height H (the front speed of a dam
// break of depth H, Ritter 1892), nu the apparent kinematic viscosity at the shear rate U_max / L
// and L the flow's length scale (given, or the fluid's narrowest extent). With mach_factor 10 the
// dam-break estimate gives c0 = 20 sqrt(g H), the DualSPHysics default.
#include "materials/rheology.hpp"
#include "particles/particle_store.hpp"
#include "sph/config.hpp"

namespace partimix::sph {

// Height of the fluid along `gravity`: from the lowest to the highest fluid particle plus one
// spacing (each particle stands for a cell of size dp). 0 when gravity is zero.
double fluid_height(const ParticleStore& store, const Vec3& gravity, double spacing);

// The fluid's narrowest extent over the first `dimensions` axes, plus one spacing.
double fluid_narrowest_extent(const ParticleStore& store, int dimensions, double spacing);

// U_max: sph.max_velocity, or 2 sqrt(|g| H). Throws InputError naming sph.max_velocity when
// neither gives a positive speed.
double estimated_max_velocity(const Config& config, const ParticleStore& store,
                              const Vec3& hydrostatic_gravity);

// Throws InputError naming sph.max_velocity when no estimate is possible.
double resolve_sound_speed(const Config& config, const ParticleStore& store,
                           const Vec3& hydrostatic_gravity,
                           const materials::BoundedRheology& rheology, double density,
                           int dimensions);

}  // namespace partimix::sph
