#pragma once
// The particles of an SPH case (docs/sph.md, "Particles"; docs/geometry-meshes.md): the fluid
// regions on the lattice, less what solid walls block, then the wall layers of every wall of
// the case's walls section, each wall a body with its motion; the tracer tagged.
#include <memory>
#include <string>
#include <vector>

#include "geometry/moving_bodies.hpp"
#include "io/case.hpp"
#include "io/method_type.hpp"
#include "particles/particle_store.hpp"
#include "sph/sph_section.hpp"

namespace partimix::sph {

// The number of wall layers: sph.wall_layers, or enough to cover the kernel support.
int wall_layers_for(const Config& config);

// Fills the instance's store (empty) with the fluid and then the wall particles of the case
// (ids in creation order), tags the tracer fluid, and makes its bodies (one per wall). With
// sph.scheme: multi_material, the integer field "material" holds each particle's region's
// material. Adds to
// its warnings what the case should hear, and to its load caveats the bodies thinner than the
// kernel support. Throws InputError naming the case key when the case cannot be built.
void generate_particles(const io::Case& the_case, const SphSection& section,
                        io::MethodInstance& instance);

}  // namespace partimix::sph
