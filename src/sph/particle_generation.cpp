#include "sph/particle_generation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "geometry/lattice.hpp"
#include "io/method_type.hpp"
#include "sph/body_clearance.hpp"
#include "sph/kernel.hpp"

namespace partimix::sph {
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

// Field "solid" (not written): 1 for the particles of a solid body from `first` on, 0 for the
// rest; the wall loads take a solid body's uniform pressure from its own particles
// (sph/wall_forces.hpp).
void mark_solid(std::vector<std::int32_t>& flag, std::size_t first, bool solid) {
  std::fill(flag.begin() + static_cast<std::ptrdiff_t>(first), flag.end(), solid ? 1 : 0);
}

void check_inside_domain(const io::Case& the_case, const ParticleStore& store) {
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!the_case.domain.contains(store.position()[i])) {
      const Vec3& x = store.position()[i];
      throw io::case_error(the_case, "domain",
                           fmt::format("a {} particle at ({:.6g}, {:.6g}, {:.6g}) lies outside "
                                       "the domain; enlarge domain.min/max",
                                       store.is_fluid(i) ? "fluid" : "wall", x.x(), x.y(), x.z()));
    }
  }
}

// The kernel support 2h (every kernel of partimix reaches `support` h) in spacings.
double kernel_reach(const Config& config) {
  const auto kernel = kernel_registry().create(config.kernel);
  const double support = kernel ? kernel->support() : 2.0;
  return support * config.smoothing_ratio;
}

// The lattice of the case (sph.lattice), with the case's limits for one that adds to the
// `existing` particles of the store.
geometry::LatticeOptions lattice_after(const io::Case& the_case, const Config& config,
                                       std::size_t existing) {
  return {config.polar_centre, config.golden_rings, the_case.limits.lattice_points,
          the_case.limits.particles - static_cast<double>(existing)};
}

// sample(), with a lattice that passes the case's limits reported at `key`.
template <class Sample>
std::vector<Vec3> located(const io::Case& the_case, const std::string& key, Sample&& sample) {
  try {
    return sample();
  } catch (const InputError& error) {
    throw io::case_error(the_case, key, error.message());
  }
}

// The fluid lattice points of region `r`, less those that the solid bodies block and those an
// earlier region holds (a point inside several regions is laid once, by the first).
std::vector<Vec3> fluid_points(const io::Case& the_case, const Config& config,
                               const FluidSpec& fluid, std::size_t r, std::size_t existing,
                               const BodyClearance& clearance) {
  const double spacing = config.spacing;
  const std::string key = fmt::format("fluid.regions[{}]", r);
  std::vector<Vec3> points = located(the_case, key, [&] {
    return geometry::fill(*fluid.regions[r].shape, spacing, the_case.domain,
                          lattice_after(the_case, config, existing));
  });
  if (points.empty()) {
    throw io::case_error(the_case, key,
                         fmt::format("no lattice point at spacing {:.6g} m lies inside this "
                                     "region within the domain",
                                     spacing));
  }
  std::erase_if(points, [&](const Vec3& x) {
    return clearance.blocks(x) ||
           std::any_of(fluid.regions.begin(),
                       fluid.regions.begin() + static_cast<std::ptrdiff_t>(r),
                       [&](const FluidRegion& earlier) {
                         return geometry::fills(*earlier.shape, x, the_case.domain);
                       });
  });
  return points;
}

// The wall particles of wall `w`: layers inside a solid body, outside a container.
std::vector<Vec3> wall_points(const io::Case& the_case, const Config& config, std::size_t w,
                              std::size_t existing) {
  const io::WallSpec& wall = the_case.walls[w];
  const std::string key = fmt::format("walls[{}]", w);
  const geometry::LatticeOptions lattice = lattice_after(the_case, config, existing);
  const double spacing = config.spacing;
  const int layers = wall_layers_for(config);
  if (!wall.solid) {
    return located(the_case, key, [&] {
      return geometry::wall_layers(*wall.shape, spacing, layers, wall.open_faces, the_case.domain,
                                   lattice);
    });
  }
  // Twice the layers of a container: the particles within the fluid's reach then see the body
  // around them in full, which the loads' area vectors need (docs/power.md, "Uniform parts of
  // the load").
  std::vector<Vec3> points = located(the_case, key, [&] {
    return geometry::inside_layers(*wall.shape, spacing, 2 * layers, the_case.domain, lattice);
  });
  if (points.empty()) {
    throw io::case_error(the_case, key,
                         "no lattice point lies inside this solid wall: it is thinner than about "
                         "half a spacing; make it thicker or sph.spacing smaller");
  }
  return points;
}

// Why the loads on solid wall `w` (its particles `points`) are unreliable, when it is thinner
// than the kernel support 2h everywhere (docs/geometry-meshes.md, "Bodies thinner than the
// kernel support"): the fluid on its two sides interacts through it. Its thickness is taken as
// 2 d + dp, d the depth of its deepest particle below the surface: exact for a slab whose
// middle holds a lattice plane, within a spacing otherwise.
std::optional<std::string> see_through(const io::Case& the_case, const Config& config,
                                       std::size_t w, const std::vector<Vec3>& points) {
  const io::WallSpec& wall = the_case.walls[w];
  if (!wall.solid)
    return std::nullopt;
  double depth = 0.0;
  for (const Vec3& x : points)
    depth = std::max(depth, -wall.shape->signed_distance(x));
  const double spacing = config.spacing;
  const double thickness = 2.0 * depth + spacing;
  const double support = kernel_reach(config) * spacing;
  if (thickness >= support - 1e-9 * spacing)
    return std::nullopt;
  return fmt::format(
      "walls[{}] is about {:.3g} m thick at its thickest, less than the kernel support 2h = "
      "{:.3g} m: the fluid on its two sides interacts through it, so fluid leaks across it and "
      "the loads on it come out too small; make it at least 2h thick or sph.spacing at most "
      "{:.3g} m",
      w, thickness, support, spacing * thickness / support);
}

// The depth below its wall's surface and the surface's unit normal towards the fluid of each
// wall particle from `first` on (fields "surface_depth" and "surface_normal"), from the wall
// shape's signed distance and its gradient by central differences; the extrapolated ghost
// velocity needs both (docs/sph.md, "Walls"). Where the gradient vanishes (a body's medial
// axis) the normal is left zero.
void mark_surface(const io::WallSpec& wall, int dimensions, double spacing, std::size_t first,
                  ParticleStore& store) {
  std::vector<double>& depth = store.find_scalar("surface_depth")->values;
  std::vector<Vec3>& normal = store.find_vector("surface_normal")->values;
  const double step = 1e-3 * spacing;
  const double towards_fluid = wall.solid ? 1.0 : -1.0;
  for (std::size_t i = first; i < store.size(); ++i) {
    const Vec3& x = store.position()[i];
    Vec3 gradient = Vec3::Zero();
    for (int axis = 0; axis < dimensions; ++axis) {
      const Vec3 offset = step * Vec3::Unit(axis);
      gradient[axis] =
          (wall.shape->signed_distance(x + offset) - wall.shape->signed_distance(x - offset)) /
          (2.0 * step);
    }
    depth[i] = std::abs(wall.shape->signed_distance(x));
    const double length = gradient.norm();
    normal[i] = length > 0.5 ? Vec3((towards_fluid / length) * gradient) : Vec3::Zero();
  }
}

// Tag 1 for the tracer fluid (fluid.tracer), 0 for the rest: the mixing analyses and the colour
// of the VTK frames (field "tag").
void tag_tracer(const FluidSpec& fluid, ParticleStore& store) {
  if (!fluid.tracer)
    return;
  const TracerPlane& plane = *fluid.tracer;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const bool tracer = (store.position()[i] - plane.point).dot(plane.normal) > 0.0;
    store.tag()[i] = store.is_fluid(i) && tracer ? 1 : 0;
  }
}

}  // namespace

int wall_layers_for(const Config& config) {
  if (config.wall_layers)
    return *config.wall_layers;
  return static_cast<int>(std::ceil(kernel_reach(config) - 1e-9));
}

void generate_particles(const io::Case& the_case, const SphSection& section,
                        io::MethodInstance& instance) {
  ParticleStore& store = *instance.store;
  // The solid bodies first: the fluid keeps clear of their particles.
  std::vector<std::vector<Vec3>> bodies(the_case.walls.size());
  BodyClearance clearance(the_case.domain, section.config.spacing);
  std::size_t pending = 0;
  for (std::size_t w = 0; w < the_case.walls.size(); ++w) {
    if (!the_case.walls[w].solid)
      continue;
    bodies[w] = wall_points(the_case, section.config, w, pending);
    clearance.add_body(*the_case.walls[w].shape, bodies[w]);
    pending += bodies[w].size();
  }
  std::vector<std::int32_t> material;
  for (std::size_t r = 0; r < section.fluid.regions.size(); ++r) {
    append(
        store,
        fluid_points(the_case, section.config, section.fluid, r, store.size() + pending, clearance),
        ParticleKind::fluid);
    material.resize(store.size(), section.fluid.regions[r].material);
  }
  if (section.config.scheme == "multi_material")
    store.add_integer("material", "").values = std::move(material);
  instance.bodies = std::make_unique<geometry::MovingBodies>(store, the_case.domain);
  std::vector<std::int32_t>& solid = store.add_integer("solid", "", false).values;
  store.add_scalar("surface_depth", "m", false);
  for (std::size_t w = 0; w < the_case.walls.size(); ++w) {
    const io::WallSpec& wall = the_case.walls[w];
    const std::size_t first = store.size();
    pending -= bodies[w].size();
    const std::vector<Vec3> points =
        wall.solid ? std::move(bodies[w])
                   : wall_points(the_case, section.config, w, store.size() + pending);
    if (auto reason = see_through(the_case, section.config, w, points)) {
      instance.warnings.push_back(fmt::format("{}: {}", the_case.file, *reason));
      instance.load_caveats[static_cast<int>(w)] = std::move(*reason);
    }
    append(store, points, ParticleKind::wall);
    mark_solid(solid, first, wall.solid);
    mark_surface(wall, the_case.domain.dimensions, section.config.spacing, first, store);
    auto motion = geometry::motion_registry().create(wall.motion.type, wall.motion);
    if (!motion) {
      throw io::case_error(the_case, fmt::format("walls[{}].motion.type", w),
                           "unknown motion '" + wall.motion.type + "'");
    }
    instance.bodies->add_body(first, std::move(motion));
  }
  if (store.size() == 0)
    throw io::case_error(the_case, "fluid.regions", "the case generates no particles");
  check_inside_domain(the_case, store);
  tag_tracer(section.fluid, store);
}

}  // namespace partimix::sph
