#include "mpm/mpm_section.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "io/shape_section.hpp"

namespace partimix::mpm {
namespace {

using io::at_least;
using io::kNonNegative;
using io::kPositive;
using io::Reader;

materials::GranularMaterial read_material(Reader& item) {
  materials::GranularMaterial m;
  m.name = item.required<std::string>("name");
  m.density = item.required<double>("density", kPositive);
  m.packing_fraction = item.optional<double>("packing_fraction", m.packing_fraction, kPositive);
  if (m.packing_fraction > 1.0)
    throw item.error("packing_fraction", "must lie in (0, 1]");
  m.youngs_modulus = item.required<double>("youngs_modulus", kPositive);
  m.poisson_ratio = item.optional<double>("poisson_ratio", m.poisson_ratio, kNonNegative);
  if (!(m.poisson_ratio < 0.5))
    throw item.error("poisson_ratio", "must lie in [0, 0.5)");
  m.grain_diameter = item.required<double>("grain_diameter", kPositive);
  m.mu_s = item.required<double>("mu_s", kNonNegative);
  m.mu_2 = item.required<double>("mu_2", kNonNegative);
  if (m.mu_2 < m.mu_s)
    throw item.error("mu_2", fmt::format("must be at least mu_s = {}", m.mu_s));
  m.i0 = item.required<double>("i0", kPositive);
  return m;
}

std::vector<materials::GranularMaterial> read_materials(Reader& section) {
  std::vector<materials::GranularMaterial> result;
  for (Reader& item : section.list("materials")) {
    result.push_back(read_material(item));
    for (std::size_t k = 0; k + 1 < result.size(); ++k) {
      if (result[k].name == result.back().name)
        throw item.error("name", fmt::format("a second material named '{}'", result[k].name));
    }
    item.done();
  }
  return result;
}

int material_index(Reader& item, const std::vector<materials::GranularMaterial>& materials) {
  const std::string name = item.optional<std::string>("material", materials.front().name);
  for (std::size_t k = 0; k < materials.size(); ++k) {
    if (materials[k].name == name)
      return static_cast<int>(k);
  }
  throw item.error("material", fmt::format("no material named '{}' in mpm.materials", name));
}

// A region of points: the shapes of fluid and grain regions, and in 3D a cone (a hopper's
// inside).
std::shared_ptr<const geometry::Shape> read_region(Reader& item, int dimensions,
                                                   const std::filesystem::path& folder) {
  Reader region = item.map("region");
  std::vector<std::string> kinds{"box", "cylinder", "plate", "mesh"};
  if (dimensions == 3)
    kinds.push_back("cone");
  const std::string kind = region.required_choice("shape", kinds);
  auto shape = io::read_shape_of(kind, region, dimensions, folder);
  region.done();
  return shape;
}

PointFill read_fill(Reader& item, const MpmConfig& config, int dimensions,
                    const std::filesystem::path& folder) {
  PointFill fill;
  fill.region = read_region(item, dimensions, folder);
  fill.spacing = item.required<double>("spacing", kPositive);
  if (fill.spacing > config.cell_size)
    throw item.error("spacing", fmt::format("must be at most mpm.cell_size = {:.6g} m (at least "
                                            "one point per cell along each axis)",
                                            config.cell_size));
  fill.material = material_index(item, config.materials);
  fill.tag = item.optional<int>("tag", 0, at_least(0));
  fill.velocity = item.vector("velocity", dimensions, Vec3::Zero());
  fill.geostatic = item.choice("initial_stress", "none", {"none", "geostatic"}) == "geostatic";
  if (item.contains("lateral_stress_ratio"))
    fill.lateral_stress_ratio = item.required<double>("lateral_stress_ratio", kNonNegative);
  return fill;
}

GridWall grid_wall(const io::WallSpec& wall) {
  GridWall result;
  result.surface = wall.surface;
  result.motion = wall.motion;
  result.boundary = wall.boundary == "slip"       ? GridBoundary::slip
                    : wall.boundary == "friction" ? GridBoundary::friction
                                                  : GridBoundary::no_slip;
  result.friction = wall.material.friction.value_or(0.0);
  return result;
}

void read_numerics(Reader& section, MpmConfig& config) {
  config.cell_size = section.required<double>("cell_size", kPositive);
  config.shape_function =
      section.choice("shape_function", config.shape_function, {"bspline", "gimp", "linear"});
  config.apic = section.choice("transfer", "apic", {"apic", "flip"}) == "apic";
  config.filter_time = section.automatic<double>("filter_time", kNonNegative);
  config.musl = section.choice("update", "musl", {"musl", "usl"}) == "musl";
  config.averaged_dilation =
      section.choice("dilation", "local", {"local", "averaged"}) == "averaged";
  config.cfl = section.optional<double>("cfl", config.cfl, kPositive);
  if (config.cfl > 1.0)
    throw section.error("cfl", "must lie in (0, 1]");
}

}  // namespace

std::shared_ptr<MpmSection> read_mpm_section(Reader& root, const io::Case& the_case) {
  Reader section = root.map("mpm");
  auto spec = std::make_shared<MpmSection>();
  MpmConfig& config = spec->config;
  read_numerics(section, config);
  config.max_grid_nodes = the_case.limits.grid_nodes;
  config.materials = read_materials(section);
  const std::filesystem::path folder = std::filesystem::path(the_case.file).parent_path();
  for (Reader& item : section.list("fill")) {
    config.fills.push_back(read_fill(item, config, the_case.domain.dimensions, folder));
    item.done();
  }
  for (const io::WallSpec& wall : the_case.walls)
    config.walls.push_back(grid_wall(wall));
  for (Reader& item : section.optional_list("exits")) {
    PointExit exit;
    exit.point = item.vector("point", the_case.domain.dimensions);
    const Vec3 normal = item.vector("normal", the_case.domain.dimensions);
    if (!(normal.norm() > 0.0))
      throw item.error("normal", "must not be zero");
    exit.normal = normal.normalized();
    item.done();
    config.exits.push_back(exit);
  }
  for (Reader& item : section.optional_list("feeds")) {
    PointFeed feed;
    feed.region = read_region(item, the_case.domain.dimensions, folder);
    feed.spacing = item.required<double>("spacing", kPositive);
    feed.material = material_index(item, config.materials);
    feed.tag = item.optional<int>("tag", 0, at_least(0));
    feed.velocity = item.vector("velocity", the_case.domain.dimensions, Vec3::Zero());
    item.done();
    config.feeds.push_back(feed);
  }
  section.done();
  return spec;
}

}  // namespace partimix::mpm
