#include "dem/dem_section.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "core/error.hpp"
#include "dem/grain_list.hpp"
#include "io/shape_section.hpp"

namespace partimix::dem {
namespace {

using io::at_least;
using io::kNonNegative;
using io::kPositive;
using io::Reader;

Material read_material(Reader& section, const Material& fallback) {
  return {section.optional<double>("youngs_modulus", fallback.youngs_modulus, kPositive),
          section.optional<double>("poisson_ratio", fallback.poisson_ratio, kNonNegative)};
}

// `shape`: a superquadric by its half-axes, or by the seed's aspect ratio sigma = c / a (a = b)
// and the radius of the sphere of the same volume; blockiness [n1, n2] (default [2, 2], an
// ellipsoid). docs/dem.md, "Superquadric grains".
Superquadric read_shape(Reader& shape) {
  const Vec3 blockiness = shape.vector("blockiness", 2, Vec3(2.0, 2.0, 0.0));
  if (!(blockiness.x() >= 2.0 && blockiness.x() <= 20.0 && blockiness.y() >= 2.0 &&
        blockiness.y() <= 20.0))
    throw shape.error("blockiness", "n1 and n2 must lie in [2, 20]");
  if (shape.contains("half_axes") == shape.contains("aspect_ratio")) {
    throw shape.error("half_axes",
                      "give either half_axes [a, b, c] or aspect_ratio (c / a, a = b) with "
                      "equivalent_radius");
  }
  if (shape.contains("half_axes")) {
    const Vec3 axes = shape.vector("half_axes", 3);
    if (!(axes.minCoeff() > 0.0) || !std::isfinite(axes.maxCoeff()))
      throw shape.error("half_axes", "the half-axes must be positive and finite");
    return Superquadric(axes, blockiness.x(), blockiness.y());
  }
  const double sigma = shape.required<double>("aspect_ratio", kPositive);
  const double radius = shape.required<double>("equivalent_radius", kPositive);
  if (sigma > 100.0 || sigma < 0.01)
    throw shape.error("aspect_ratio", "must lie in [0.01, 100]");
  const Superquadric unit(Vec3(1.0, 1.0, sigma), blockiness.x(), blockiness.y());
  const double a = radius * std::cbrt(4.0 / 3.0 * std::numbers::pi / unit.volume());
  return Superquadric(Vec3(a, a, sigma * a), blockiness.x(), blockiness.y());
}

// `hertz_radius` and `curvature_limit` (docs/dem.md, "Hertz radius").
void read_hertz_radius(Reader& section, Config& config) {
  const std::string kind = section.choice("hertz_radius", "equivalent",
                                          {"equivalent", "mean_curvature", "gaussian_curvature"});
  config.hertz_radius = kind == "equivalent"       ? HertzRadius::equivalent
                        : kind == "mean_curvature" ? HertzRadius::mean_curvature
                                                   : HertzRadius::gaussian_curvature;
  config.curvature_limit =
      section.optional<double>("curvature_limit", config.curvature_limit, at_least(1.0));
}

std::vector<Species> read_species(Reader& section) {
  std::vector<Species> species;
  for (Reader& item : section.list("species")) {
    Species s;
    s.name = item.required<std::string>("name");
    if (s.name == "wall")
      throw item.error("name", "'wall' names the walls in interactions.pairs; choose another");
    s.density = item.required<double>("density", kPositive);
    s.material = read_material(item, s.material);
    if (item.contains("shape")) {
      Reader shape = item.map("shape");
      s.shape = read_shape(shape);
      shape.done();
    }
    item.done();
    species.push_back(s);
  }
  if (species.size() > 2)
    throw section.error("species", "at most two species (0 and 1, the tracer) for now");
  return species;
}

Interaction read_interaction(Reader& section, const Interaction& fallback) {
  Interaction i;
  i.restitution = section.optional<double>("restitution", fallback.restitution, kPositive);
  if (i.restitution > 1.0)
    throw section.error("restitution", "must lie in (0, 1]");
  i.friction = section.optional<double>("friction", fallback.friction, kNonNegative);
  i.rolling_friction =
      section.optional<double>("rolling_friction", fallback.rolling_friction, kNonNegative);
  return i;
}

// The index of the species named by `key`; -1 for "wall" (the walls).
int species_index(Reader& item, const std::string& key, const std::vector<Species>& species) {
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
void read_interactions(Reader& section, Config& config) {
  Reader interactions = section.optional_map("interactions");
  Reader particle = interactions.optional_map("particle");
  const Interaction grains = read_interaction(particle, {});
  particle.done();
  Reader wall = interactions.optional_map("wall");
  const Interaction walls = read_interaction(wall, grains);
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

// One wall of the case as the grains see it: the species' interactions with it are the wall
// material's coefficients where it gives them, dem.interactions' otherwise.
WallConfig wall_config(const io::WallSpec& wall, const std::vector<Interaction>& defaults) {
  WallConfig config{wall.surface,
                    wall.motion,
                    Material{wall.material.youngs_modulus, wall.material.poisson_ratio},
                    {}};
  const io::WallMaterial& m = wall.material;
  if (!m.restitution && !m.friction && !m.rolling_friction)
    return config;
  for (const Interaction& fallback : defaults) {
    config.interactions.push_back({m.restitution.value_or(fallback.restitution),
                                   m.friction.value_or(fallback.friction),
                                   m.rolling_friction.value_or(fallback.rolling_friction)});
  }
  return config;
}

// The walls are the case's shared ones; the keys that held DEM walls before say where they are.
void refuse_old_wall_keys(Reader& section) {
  for (const std::string key : {"walls", "wall_material"}) {
    if (section.contains(key)) {
      throw section.error(key,
                          "DEM walls are now the case's top-level `walls:` list, shared by "
                          "every method: move each item there with `shape:` in place of "
                          "`surface:` and give it `material: {youngs_modulus, poisson_ratio}` "
                          "(docs/case-reference.md, \"walls\")");
    }
  }
}

// The fill's grain size: `radius` (and `radius_max`) for spheres; for superquadrics their
// bounding spheres, inserted without overlap (both species of one shape, as the split after
// settling may turn a grain of one into the other).
void read_fill_size(Reader& fill, const std::vector<Species>& species, InsertionRequest& request) {
  if (const auto& shape = species.front().shape) {
    for (const Species& other : species) {
      if (!other.shape || other.shape->half_axes() != shape->half_axes() ||
          other.shape->n1() != shape->n1() || other.shape->n2() != shape->n2())
        throw fill.error("split", "a fill of superquadrics needs both species of one shape");
    }
    if (fill.contains("radius") || fill.contains("radius_max"))
      throw fill.error("radius", "superquadric grains take their size from species[].shape");
    request.radius_min = request.radius_max = shape->bounding_radius();
    request.shape = shape;
    return;
  }
  if (species.back().shape)
    throw fill.error("split", "a fill of spheres needs both species to be spheres");
  request.radius_min = fill.required<double>("radius", kPositive);
  request.radius_max = fill.optional<double>("radius_max", request.radius_min, kPositive);
  if (request.radius_max < request.radius_min)
    throw fill.error("radius_max", "must be at least radius");
}

GrainFill read_fill(Reader& section, const std::filesystem::path& folder,
                    const io::SizeLimits& limits, const std::vector<Species>& species) {
  Reader fill = section.map("fill");
  GrainFill result;
  Reader region = fill.map("region");
  result.region = io::read_shape(region, 3, folder);
  region.done();
  InsertionRequest& request = result.insertion;
  request.count = fill.required<int>("count", at_least(1));
  if (request.count > limits.particles) {
    throw fill.error("count", fmt::format("{} grains are more than limits.particles = {:.3g}; "
                                          "raise the limit if the run is meant to be this big",
                                          request.count, limits.particles));
  }
  read_fill_size(fill, species, request);
  request.seed = static_cast<std::uint32_t>(fill.optional<int>("seed", 1, at_least(0)));
  request.attempts_per_grain =
      fill.optional<int>("attempts", request.attempts_per_grain, at_least(1));
  if (request.attempts_per_grain > kMostAttempts) {
    throw fill.error("attempts",
                     fmt::format("more than {:.0e} failed candidates in a row would let "
                                 "a full region hold the run for minutes",
                                 static_cast<double>(kMostAttempts)));
  }
  result.settle_energy = fill.optional<double>("settle_energy", result.settle_energy, kPositive);
  result.settle_time = fill.optional<double>("settle_time", result.settle_time, kNonNegative);
  Reader split = fill.optional_map("split");
  result.split_point = split.vector("point", 3, result.split_point);
  result.split_normal = split.vector("normal", 3, result.split_normal);
  split.done();
  fill.done();
  return result;
}

// Exactly one of `fill` (random, settled), `grains` (a list) and `grains_file` (CSV).
void read_grains(Reader& section, const io::Case& the_case, DemSection& spec) {
  const std::filesystem::path folder = std::filesystem::path(the_case.file).parent_path();
  const std::vector<std::string> ways{"fill", "grains", "grains_file"};
  std::vector<std::string> given;
  for (const std::string& key : ways) {
    if (section.contains(key))
      given.push_back(key);
  }
  if (given.size() != 1) {
    throw section.error(given.empty() ? "fill" : given[1],
                        "give exactly one of fill (a random fill), grains (a list) and "
                        "grains_file (a CSV file)");
  }
  if (given[0] == "fill") {
    spec.fill = read_fill(section, folder, the_case.limits, spec.config.species);
  } else if (given[0] == "grains") {
    spec.grains = read_grain_list(section, spec.config.species, the_case.limits);
  } else {
    const std::string file = section.required<std::string>("grains_file");
    spec.grains = read_grain_file(folder / file, spec.config.species, the_case.limits);
  }
  spec.grains_key = "dem." + given[0];
}

}  // namespace

bool DemSection::has_grain_axes() const {
  return std::any_of(config.species.begin(), config.species.end(), [](const Species& s) {
    return s.shape && (s.shape->half_axes().array() != s.shape->half_axes().x()).any();
  });
}

std::shared_ptr<DemSection> read_dem_section(Reader& root, const io::Case& the_case) {
  if (the_case.domain.dimensions != 3)
    throw root.error("dimensions", "the DEM solver needs dimensions: 3");
  Reader section = root.map("dem");
  refuse_old_wall_keys(section);
  auto spec = std::make_shared<DemSection>();
  Config& config = spec->config;
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
  config.neighbour_skin =
      section.optional<double>("neighbour_skin", config.neighbour_skin, kPositive);
  if (config.neighbour_skin > 4.0) {
    throw section.error("neighbour_skin",
                        "must be at most 4 largest radii (a wider skin lists far more pairs "
                        "than touch)");
  }
  read_hertz_radius(section, config);
  config.species = read_species(section);
  read_interactions(section, config);
  for (const io::WallSpec& wall : the_case.walls)
    config.walls.push_back(wall_config(wall, config.wall_interactions));
  read_grains(section, the_case, *spec);
  section.done();
  return spec;
}

}  // namespace partimix::dem
