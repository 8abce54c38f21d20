#include "app/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "app/dem_simulation.hpp"
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

// The kernel support 2h (every kernel of partimix reaches `support` h) in spacings.
double kernel_reach(const sph::Config& config) {
  const auto kernel = sph::kernel_registry().create(config.kernel);
  const double support = kernel ? kernel->support() : 2.0;
  return support * config.smoothing_ratio;
}

int wall_layers_for(const sph::Config& config) {
  if (config.wall_layers)
    return *config.wall_layers;
  return static_cast<int>(std::ceil(kernel_reach(config) - 1e-9));
}

// Whether `x` lies inside the solid wall or closer than half a spacing to its surface, where
// the fluid must clear the body (docs/geometry-meshes.md, "Solid walls").
// The bounding-box test first spares most fluid points the distance query (costly for a mesh).
bool blocked_by(const io::WallSpec& wall, const Vec3& x, double spacing) {
  if (!wall.solid)
    return false;
  const double clearance = 0.5 * spacing;
  const Vec3 lo = wall.shape->lower().array() - clearance;
  const Vec3 hi = wall.shape->upper().array() + clearance;
  const bool near_box = (x.array() > lo.array()).all() && (x.array() < hi.array()).all();
  return near_box && wall.shape->signed_distance(x) < clearance;
}

// The fluid lattice points of `region`, less those that a solid wall blocks.
std::vector<Vec3> fluid_points(const io::Case& the_case, const io::FluidRegion& region) {
  const double spacing = the_case.sph.spacing;
  std::vector<Vec3> points = geometry::fill(*region.shape, spacing, the_case.domain);
  std::erase_if(points, [&](const Vec3& x) {
    return std::any_of(the_case.walls.begin(), the_case.walls.end(),
                       [&](const io::WallSpec& wall) { return blocked_by(wall, x, spacing); });
  });
  return points;
}

// The wall particles of wall `w`: layers inside a solid body, outside a container.
std::vector<Vec3> wall_points(const io::Case& the_case, std::size_t w, int layers) {
  const io::WallSpec& wall = the_case.walls[w];
  const double spacing = the_case.sph.spacing;
  if (!wall.solid) {
    return geometry::wall_layers(*wall.shape, spacing, layers, wall.open_faces, the_case.domain);
  }
  std::vector<Vec3> points = geometry::inside_layers(*wall.shape, spacing, layers, the_case.domain);
  if (points.empty()) {
    throw case_error(the_case, fmt::format("walls[{}]", w),
                     "no lattice point lies inside this solid wall: it is thinner than about half "
                     "a spacing; make it thicker or sph.spacing smaller");
  }
  return points;
}

// A warning when solid wall `w` (its particles `points`) is thinner than the kernel support 2h
// everywhere (docs/geometry-meshes.md, "Bodies thinner than the kernel support"). Its thickness
// is taken as 2 d + dp, d the depth of its deepest particle below the surface: exact for a slab
// whose middle holds a lattice plane, within a spacing otherwise.
std::optional<std::string> see_through_warning(const io::Case& the_case, std::size_t w,
                                               const std::vector<Vec3>& points) {
  const io::WallSpec& wall = the_case.walls[w];
  if (!wall.solid)
    return std::nullopt;
  double depth = 0.0;
  for (const Vec3& x : points)
    depth = std::max(depth, -wall.shape->signed_distance(x));
  const double spacing = the_case.sph.spacing;
  const double thickness = 2.0 * depth + spacing;
  const double support = kernel_reach(the_case.sph) * spacing;
  if (thickness >= support - 1e-9 * spacing)
    return std::nullopt;
  return fmt::format(
      "{}: walls[{}]: this solid wall is about {:.3g} m thick at its thickest, less than the "
      "kernel support 2h = {:.3g} m: the fluid on its two sides interacts through it, so fluid "
      "leaks across it and the loads on it come out too small; make it at least 2h thick or "
      "sph.spacing at most {:.3g} m",
      the_case.file, w, thickness, support, spacing * thickness / support);
}

// Fills `store` with the fluid regions and then the wall layers of the case (ids in creation
// order), each wall a body with its motion; adds to `warnings` what the case should hear.
std::unique_ptr<geometry::MovingBodies> generate_particles(const io::Case& the_case,
                                                           int wall_layers, ParticleStore& store,
                                                           std::vector<std::string>& warnings) {
  for (const auto& region : the_case.fluid.regions) {
    append(store, fluid_points(the_case, region), ParticleKind::fluid);
  }
  auto bodies = std::make_unique<geometry::MovingBodies>(store, the_case.domain);
  for (std::size_t w = 0; w < the_case.walls.size(); ++w) {
    const io::WallSpec& wall = the_case.walls[w];
    const std::size_t first = store.size();
    const std::vector<Vec3> points = wall_points(the_case, w, wall_layers);
    if (auto warning = see_through_warning(the_case, w, points))
      warnings.push_back(std::move(*warning));
    append(store, points, ParticleKind::wall);
    auto motion = geometry::motion_registry().create(wall.motion.type, wall.motion);
    if (!motion) {
      throw case_error(the_case, fmt::format("walls[{}].motion.type", w),
                       "unknown motion '" + wall.motion.type + "'");
    }
    bodies->add_body(first, std::move(motion));
  }
  return bodies;
}

// Tag 1 for the tracer fluid (fluid.tracer), 0 for the rest: the mixing analyses and the colour
// of the VTK frames (field "tag").
void tag_tracer(const io::Case& the_case, ParticleStore& store) {
  if (!the_case.fluid.tracer)
    return;
  const io::TracerPlane& plane = *the_case.fluid.tracer;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const bool tracer = (store.position()[i] - plane.point).dot(plane.normal) > 0.0;
    store.tag()[i] = store.is_fluid(i) && tracer ? 1 : 0;
  }
}

}  // namespace

InputError case_error(const io::Case& the_case, const std::string& key, const std::string& what) {
  return InputError(InputLocation{the_case.file, 0, 0, key}, what);
}

Simulation build_simulation(const io::Case& the_case) {
  if (the_case.solver == "dem")
    return build_dem_simulation(the_case);
  Simulation simulation;
  simulation.store = std::make_unique<ParticleStore>();
  simulation.bodies = generate_particles(the_case, wall_layers_for(the_case.sph), *simulation.store,
                                         simulation.warnings);
  if (simulation.store->size() == 0) {
    throw case_error(the_case, "fluid.regions", "the case generates no particles");
  }
  check_inside_domain(the_case, *simulation.store);
  tag_tracer(the_case, *simulation.store);
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
