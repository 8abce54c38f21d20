#include "app/simulation.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "geometry/lattice.hpp"
#include "sph/kernel.hpp"
#include "sph/wcsph_solver.hpp"

namespace partimix::app {
namespace {

void append(ParticleStore& store, const std::vector<Vec3>& points, ParticleKind kind) {
  const std::size_t first = store.size();
  store.resize(first + points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    store.position()[first + k] = points[k];
    store.kind()[first + k] = static_cast<std::int32_t>(kind);
    store.id()[first + k] = static_cast<std::int64_t>(first + k);
  }
}

InputError case_error(const io::Case& the_case, const std::string& key, const std::string& what) {
  return InputError(InputLocation{the_case.file, 0, 0, key}, what);
}

void check_inside_domain(const io::Case& the_case, const ParticleStore& store) {
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!the_case.domain.contains(store.position()[i])) {
      const Vec3& x = store.position()[i];
      throw case_error(the_case, "domain",
                       fmt::format("a {} particle at ({:.6g}, {:.6g}, {:.6g}) lies outside the "
                                   "domain; enlarge domain.min/max",
                                   store.is_fluid(i) ? "fluid" : "wall", x.x(), x.y(), x.z()));
    }
  }
}

int wall_layers_for(const sph::Config& config) {
  if (config.wall_layers)
    return *config.wall_layers;
  const auto kernel = sph::kernel_registry().create(config.kernel);
  const double support = kernel ? kernel->support() : 2.0;
  return static_cast<int>(std::ceil(support * config.smoothing_ratio - 1e-9));
}

// Fills `store` with the fluid regions and then the wall layers of the case (ids in creation
// order), each wall a body with its motion.
std::unique_ptr<geometry::MovingBodies> generate_particles(const io::Case& the_case,
                                                           int wall_layers, ParticleStore& store) {
  const double spacing = the_case.sph.spacing;
  for (const auto& region : the_case.fluid.regions) {
    append(store, geometry::fill(*region.shape, spacing, the_case.domain), ParticleKind::fluid);
  }
  auto bodies = std::make_unique<geometry::MovingBodies>(store, the_case.domain);
  for (std::size_t w = 0; w < the_case.walls.size(); ++w) {
    const io::WallSpec& wall = the_case.walls[w];
    const std::size_t first = store.size();
    append(
        store,
        geometry::wall_layers(*wall.shape, spacing, wall_layers, wall.open_faces, the_case.domain),
        ParticleKind::wall);
    auto motion = geometry::motion_registry().create(wall.motion.type, wall.motion);
    if (!motion) {
      throw case_error(the_case, fmt::format("walls[{}].motion.type", w),
                       "unknown motion '" + wall.motion.type + "'");
    }
    bodies->add_body(first, std::move(motion));
  }
  return bodies;
}

}  // namespace

Simulation build_simulation(const io::Case& the_case) {
  Simulation simulation;
  simulation.store = std::make_unique<ParticleStore>();
  simulation.bodies =
      generate_particles(the_case, wall_layers_for(the_case.sph), *simulation.store);
  if (simulation.store->size() == 0) {
    throw case_error(the_case, "fluid.regions", "the case generates no particles");
  }
  check_inside_domain(the_case, *simulation.store);
  try {
    simulation.solver = std::make_unique<sph::WcsphSolver>(
        *simulation.store, the_case.domain, the_case.sph,
        sph::FluidProperties{the_case.fluid.density, the_case.fluid.rheology}, the_case.gravity,
        simulation.bodies.get());
  } catch (const InputError& error) {
    throw case_error(the_case, error.location().key_path, error.message());
  }
  return simulation;
}

}  // namespace partimix::app
