#include "cfd/cfd_section.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "io/axis_names.hpp"
#include "io/method_type.hpp"
#include "io/rheology_section.hpp"
#include "io/shape_section.hpp"

namespace partimix::cfd {
namespace {

using io::at_least;
using io::kPositive;
using io::Reader;

// `light_phase: {density, viscosity}` makes the fluid two-phase: the heavy phase (the fluid's
// density and rheology) starts in `regions`, the light phase fills the other open cells. A
// region may also be a `plane`: the half-space behind it, a level under its normal.
void read_phases(Reader& fluid, const io::Case& the_case, CfdConfig& config) {
  if (!fluid.contains("light_phase"))
    return;
  Reader light = fluid.map("light_phase");
  LightPhase phase;
  phase.density = light.required<double>("density", kPositive);
  phase.viscosity = light.required<double>("viscosity", kPositive);
  phase.compression = light.optional<double>("compression", phase.compression, io::kNonNegative);
  if (!(phase.density < config.settings.density))
    throw light.error("density", fmt::format("must be below the fluid's density {} kg/m^3: the "
                                             "light phase lies above the heavy one",
                                             config.settings.density));
  light.done();
  config.settings.light_phase = phase;
  const std::filesystem::path folder = std::filesystem::path(the_case.file).parent_path();
  for (Reader& region : fluid.list("regions")) {
    const std::string shape = region.required_choice(
        "shape", {"box", "cylinder", "plate", "mesh", "truck_drum", "plane"});
    config.heavy_regions.push_back(
        io::read_shape_of(shape, region, the_case.domain.dimensions, folder));
    region.done();
  }
}

void read_fluid(Reader& root, const io::Case& the_case, CfdConfig& config) {
  Reader fluid = root.map("fluid");
  config.settings.density = fluid.required<double>("density", kPositive);
  config.settings.rheology = io::read_fluid_rheology(fluid);
  const materials::RheologyConfig& rheology = config.settings.rheology;
  if (rheology.model == "newtonian" && !(rheology.viscosity > 0.0))
    throw fluid.error("viscosity", "the cfd method needs a viscosity above zero");
  read_phases(fluid, the_case, config);
  fluid.done();
}

void read_numerics(Reader& section, FluidSettings& settings) {
  settings.convection = section.choice("convection", "tvd", {"tvd", "upwind"}) == "tvd"
                            ? ConvectionScheme::tvd
                            : ConvectionScheme::upwind;
  settings.cfl = section.optional<double>("cfl", settings.cfl, kPositive);
  if (settings.cfl > 1.0)
    throw section.error("cfl", "must lie in (0, 1]");
  settings.max_dt = section.optional<double>("max_dt", settings.max_dt, kPositive);
  settings.pressure_tolerance =
      section.optional<double>("pressure_tolerance", settings.pressure_tolerance, kPositive);
  settings.momentum_tolerance =
      section.optional<double>("momentum_tolerance", settings.momentum_tolerance, kPositive);
  settings.max_iterations =
      section.optional<int>("max_iterations", settings.max_iterations, at_least(1));
}

// `sides: {"y+": {wall: no_slip, velocity: [1, 0]}, "x-": {wall: slip}, "z+": {wall: outlet}}`;
// the others no-slip at rest. A no-slip side whose velocity crosses it is an inlet, which needs
// an outlet side.
void read_sides(Reader& section, const Domain& domain, BoxSides& sides) {
  Reader map = section.optional_map("sides");
  bool inflow = false;
  bool outlet = false;
  for (const std::string& axis_name : io::axis_names(domain.dimensions)) {
    const int axis = io::axis_index(axis_name);
    for (const char sign : {'-', '+'}) {
      const std::string key = axis_name + sign;
      if (!map.contains(key))
        continue;
      if (domain.periodic[axis])
        throw map.error(
            key, fmt::format("the domain is periodic along {}: it has no sides there", axis_name));
      Reader side = map.map(key);
      BoxSide& target = sides[static_cast<std::size_t>(2 * axis + (sign == '+' ? 1 : 0))];
      const std::string wall = side.choice("wall", "no_slip", {"no_slip", "slip", "outlet"});
      target.slip = wall == "slip";
      target.outlet = wall == "outlet";
      target.velocity = side.vector("velocity", domain.dimensions, Vec3::Zero());
      if (wall != "no_slip" && target.velocity.norm() > 0.0)
        throw side.error("velocity", fmt::format("a side of wall: {} takes no velocity", wall));
      inflow = inflow || target.velocity[axis] != 0.0;
      outlet = outlet || target.outlet;
      side.done();
    }
  }
  if (inflow && !outlet)
    throw section.error("sides",
                        "a side with a velocity across it (an inlet) needs a side of "
                        "wall: outlet");
  map.done();
}

// The times at which a moving wall is checked to stay in place: after every start-up ramp,
// over a turn of the fastest rotation (1 s without one).
InPlaceSamples in_place_samples(const io::Case& the_case) {
  InPlaceSamples samples;
  double fastest = 0.0;
  for (const io::WallSpec& wall : the_case.walls) {
    samples.start = std::max(samples.start, wall.motion.ramp_time);
    fastest = std::max({fastest, std::abs(wall.motion.rpm), std::abs(wall.motion.revolution_rpm)});
    for (const geometry::SpeedChange& change : wall.motion.schedule)
      fastest = std::max(fastest, std::abs(change.rpm));
  }
  if (fastest > 0.0)
    samples.period = 60.0 / fastest;
  return samples;
}

void read_walls(const io::Case& the_case, CfdConfig& config) {
  for (const io::WallSpec& wall : the_case.walls) {
    config.walls.push_back(wall.surface);
    config.wall_shapes.push_back(wall.shape);
    config.wall_motions.push_back(
        geometry::motion_registry().create(wall.motion.type, wall.motion));
  }
  config.in_place_samples = in_place_samples(the_case);
}

// `rotating_frame: {wall: k}`: the grid turns with wall k, in rotation about a fixed axis.
void read_frame(Reader& section, const io::Case& the_case, CfdConfig& config) {
  if (!section.contains("rotating_frame"))
    return;
  Reader frame = section.map("rotating_frame");
  const int wall = frame.required<int>("wall", at_least(0));
  if (wall >= static_cast<int>(the_case.walls.size()))
    throw frame.error("wall",
                      fmt::format("the case has {} walls (indices from 0)", the_case.walls.size()));
  if (the_case.walls[static_cast<std::size_t>(wall)].motion.type != "rotation")
    throw frame.error("wall", fmt::format("walls[{}] must be in rotation (motion: {{type: "
                                          "rotation}}): the frame turns with it about its axis",
                                          wall));
  config.frame_wall = wall;
  frame.done();
}

}  // namespace

std::shared_ptr<CfdSection> read_cfd_section(Reader& root, const io::Case& the_case) {
  auto spec = std::make_shared<CfdSection>();
  CfdConfig& config = spec->config;
  read_fluid(root, the_case, config);
  Reader section = root.map("cfd");
  config.cell_size = section.required<double>("cell_size", kPositive);
  read_numerics(section, config.settings);
  read_sides(section, the_case.domain, config.sides);
  config.settings.gravity = the_case.gravity;
  config.max_cells = the_case.limits.grid_nodes;
  read_walls(the_case, config);
  read_frame(section, the_case, config);
  section.done();
  return spec;
}

}  // namespace partimix::cfd
