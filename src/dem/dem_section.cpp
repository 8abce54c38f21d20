#include "io/dem_section.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "dem/cone_wall.hpp"
#include "dem/drum_wall.hpp"
#include "dem/mesh_wall.hpp"
#include "dem/plane_wall.hpp"
#include "geometry/stl_reader.hpp"
#include "io/motion_section.hpp"
#include "io/shape_section.hpp"

namespace partimix::io {
namespace {

dem::Material read_material(Reader& section, const dem::Material& fallback) {
  return {section.optional<double>("youngs_modulus", fallback.youngs_modulus, kPositive),
          section.optional<double>("poisson_ratio", fallback.poisson_ratio, kNonNegative)};
}

std::vector<dem::Species> read_species(Reader& section) {
  std::vector<dem::Species> species;
  for (Reader& item : section.list("species")) {
    dem::Species s;
    s.name = item.required<std::string>("name");
    if (s.name == "wall")
      throw item.error("name", "'wall' names the walls in interactions.pairs; choose another");
    s.density = item.required<double>("density", kPositive);
    s.material = read_material(item, s.material);
    item.done();
    species.push_back(s);
  }
  if (species.size() > 2)
    throw section.error("species", "at most two species (0 and 1, the tracer) for now");
  return species;
}

dem::Interaction read_interaction(Reader& section, const dem::Interaction& fallback) {
  dem::Interaction i;
  i.restitution = section.optional<double>("restitution", fallback.restitution, kPositive);
  if (i.restitution > 1.0)
    throw section.error("restitution", "must lie in (0, 1]");
  i.friction = section.optional<double>("friction", fallback.friction, kNonNegative);
  i.rolling_friction =
      section.optional<double>("rolling_friction", fallback.rolling_friction, kNonNegative);
  return i;
}

// The index of the species named by `key`; -1 for "wall" (the walls).
int species_index(Reader& item, const std::string& key, const std::vector<dem::Species>& species) {
  const std::string name = item.required<std::string>(key);
  if (name == "wall")
    return -1;
  for (std::size_t s = 0; s < species.size(); ++s) {
    if (species[s].name == name)
      return static_cast<int>(s);
  }
  throw item.error(key, "no species named '" + name + "'");
}

// `interactions`: `particle` and `wall` defaults, then `pairs` overriding single pairs.
void read_interactions(Reader& section, dem::Config& config) {
  Reader interactions = section.optional_map("interactions");
  Reader particle = interactions.optional_map("particle");
  const dem::Interaction grains = read_interaction(particle, {});
  particle.done();
  Reader wall = interactions.optional_map("wall");
  const dem::Interaction walls = read_interaction(wall, grains);
  wall.done();
  const std::size_t n = config.species.size();
  config.particle_interactions.assign(n * n, grains);
  config.wall_interactions.assign(n, walls);
  for (Reader& item : interactions.optional_list("pairs")) {
    const int a = species_index(item, "species", config.species);
    if (a < 0)
      throw item.error("species", "name a species here; 'wall' goes in 'other'");
    const int b = species_index(item, "other", config.species);
    if (b < 0) {
      config.wall_interactions[a] = read_interaction(item, walls);
    } else {
      config.particle_interactions[a * n + b] = read_interaction(item, grains);
      config.particle_interactions[b * n + a] = config.particle_interactions[a * n + b];
    }
    item.done();
  }
  interactions.done();
}

std::shared_ptr<const dem::WallSurface> read_surface(Reader& item,
                                                     const std::filesystem::path& folder) {
  const std::string surface = item.required_choice("surface", {"plane", "drum", "cone", "mesh"});
  if (surface == "plane")
    return std::make_shared<dem::PlaneWall>(item.vector("point", 3), item.vector("normal", 3));
  if (surface == "drum") {
    return std::make_shared<dem::DrumWall>(item.vector("axis_point", 3), item.vector("axis", 3),
                                           item.required<double>("radius", kPositive));
  }
  if (surface == "cone") {
    return std::make_shared<dem::ConeWall>(item.vector("axis_point", 3), item.vector("axis", 3),
                                           item.required<double>("radius_0", kNonNegative),
                                           item.required<double>("radius_1", kNonNegative),
                                           item.required<double>("height", kPositive));
  }
  const std::string file = item.required<std::string>("file");
  const double scale = item.optional<double>("scale", 1.0, kPositive);
  const Vec3 offset = item.vector("offset", 3, Vec3::Zero());
  try {
    geometry::TriangleSoup triangles = geometry::read_stl((folder / file).string(), scale);
    for (geometry::Triangle& t : triangles)
      for (Vec3& corner : t.corner)
        corner += offset;
    return std::make_shared<dem::MeshWall>(triangles);
  } catch (const InputError& error) {
    throw item.error("file", fmt::format("cannot use the mesh: {}", error.what()));
  }
}

std::vector<dem::WallConfig> read_dem_walls(Reader& section, const std::filesystem::path& folder) {
  Reader material_section = section.optional_map("wall_material");
  const dem::Material material = read_material(material_section, dem::WallConfig{}.material);
  material_section.done();
  std::vector<dem::WallConfig> walls;
  for (Reader& item : section.optional_list("walls")) {
    dem::WallConfig wall;
    wall.surface = read_surface(item, folder);
    wall.motion = read_motion(item, 3);
    wall.material = material;
    item.done();
    walls.push_back(wall);
  }
  return walls;
}

GrainFill read_fill(Reader& section, const std::filesystem::path& folder) {
  Reader fill = section.map("fill");
  GrainFill result;
  Reader region = fill.map("region");
  result.region = read_shape(region, 3, folder);
  region.done();
  dem::InsertionRequest& request = result.insertion;
  request.count = fill.required<int>("count", at_least(1));
  request.radius_min = fill.required<double>("radius", kPositive);
  request.radius_max = fill.optional<double>("radius_max", request.radius_min, kPositive);
  if (request.radius_max < request.radius_min)
    throw fill.error("radius_max", "must be at least radius");
  request.seed = static_cast<std::uint32_t>(fill.optional<int>("seed", 1, at_least(0)));
  result.settle_energy = fill.optional<double>("settle_energy", result.settle_energy, kPositive);
  result.settle_time = fill.optional<double>("settle_time", result.settle_time, kNonNegative);
  Reader split = fill.optional_map("split");
  result.split_point = split.vector("point", 3, result.split_point);
  result.split_normal = split.vector("normal", 3, result.split_normal);
  split.done();
  fill.done();
  return result;
}

}  // namespace

DemSpec read_dem(Reader& root, const std::filesystem::path& case_folder) {
  Reader section = root.map("dem");
  DemSpec spec;
  dem::Config& config = spec.config;
  config.normal_law = section.choice("normal_law", config.normal_law, {"hertz", "linear"});
  config.linear_stiffness =
      section.optional<double>("linear_stiffness", config.linear_stiffness, kNonNegative);
  if (config.normal_law == "linear" && !(config.linear_stiffness > 0.0))
    throw section.error("linear_stiffness", "the linear law needs linear_stiffness > 0");
  config.rolling_resistance = section.choice("rolling_resistance", config.rolling_resistance,
                                             {"none", "constant_torque", "elastic_plastic"});
  config.rolling_damping =
      section.optional<double>("rolling_damping", config.rolling_damping, kNonNegative);
  config.seed_tangential_cap = section.choice("tangential_cap", "none", {"none", "seed"}) == "seed";
  config.rayleigh_fraction =
      section.optional<double>("time_step_fraction", config.rayleigh_fraction, kPositive);
  config.sort_interval = section.optional<int>("sort_interval", config.sort_interval, at_least(1));
  config.species = read_species(section);
  read_interactions(section, config);
  config.walls = read_dem_walls(section, case_folder);
  spec.fill = read_fill(section, case_folder);
  section.done();
  return spec;
}

}  // namespace partimix::io
