#include "sph/sph_method.hpp"

#include <cmath>

#include <fmt/format.h>

#include "sph/free_surface.hpp"
#include "sph/multi_material/multi_material_solver.hpp"
#include "sph/particle_generation.hpp"
#include "sph/sph_solver.hpp"

namespace partimix::sph {
namespace {

// The multi-material scheme (docs/multi-material-sph.md): the regions' particles, each of its
// region's material with the mass rho0 dp^d of the material's initial density; no walls yet.
io::MethodInstance build_multi_material(const io::Case& the_case, const SphSection& section) {
  if (!the_case.walls.empty()) {
    throw io::case_error(the_case, "walls",
                         "sph.scheme: multi_material has no walls yet; a droplet or a periodic "
                         "box needs none");
  }
  io::MethodInstance instance;
  instance.store = std::make_unique<ParticleStore>();
  generate_particles(the_case, section, instance);
  ParticleStore& store = *instance.store;
  try {
    const std::vector<Material> materials = build_materials(section.config.multi_material);
    const std::vector<std::int32_t>& material = store.find_integer("material")->values;
    const double volume = std::pow(section.config.spacing, the_case.domain.dimensions);
    for (std::size_t i = 0; i < store.size(); ++i)
      store.mass()[i] = materials[static_cast<std::size_t>(material[i])].initial_density() * volume;
    instance.solver = std::make_unique<MultiMaterialSolver>(store, the_case.domain, section.config,
                                                            the_case.gravity);
  } catch (const InputError& error) {
    throw io::case_error(the_case, error.location().key_path, error.message());
  }
  return instance;
}

}  // namespace

std::shared_ptr<io::MethodSection> SphMethod::read(io::Reader& root,
                                                   const io::Case& the_case) const {
  return read_sph_section(root, the_case);
}

// Restoring a checkpoint replaces the particles' state, but the lattice defines their number
// and fields, so the build is the same either way.
io::MethodInstance SphMethod::build(const io::Case& the_case, const io::MethodSpec& spec,
                                    const io::BuildOptions& /*options*/) const {
  const auto& section = dynamic_cast<const SphSection&>(*spec.section);
  if (section.config.scheme == "multi_material")
    return build_multi_material(the_case, section);
  io::MethodInstance instance;
  instance.store = std::make_unique<ParticleStore>();
  generate_particles(the_case, section, instance);
  try {
    instance.solver =
        std::make_unique<SphSolver>(*instance.store, the_case.domain, section.config,
                                    FluidProperties{section.fluid.density, section.fluid.rheology},
                                    the_case.gravity, instance.bodies.get());
  } catch (const InputError& error) {
    throw io::case_error(the_case, error.location().key_path, error.message());
  }
  if (the_case.gravity.norm() == 0.0 &&
      has_free_surface(*instance.store, the_case.domain, section.config.spacing)) {
    instance.warnings.push_back(fmt::format(
        "{}: gravity: the fluid has a free surface but gravity is zero: nothing holds the "
        "surface, and a stirred fluid is flung out of an open vessel; close the vessel with a "
        "lid (the walls' `open`) or give gravity",
        the_case.file));
  }
  return instance;
}

}  // namespace partimix::sph
