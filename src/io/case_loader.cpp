// load_case: the case-file schema, section by section, in the order of
// docs/case-reference.md. Each section reads its keys through a Reader and ends with done(),
// which rejects the keys it did not ask for.
#include <filesystem>

#include <fmt/format.h>

#include "io/analysis_section.hpp"
#include "io/axis_names.hpp"
#include "io/case.hpp"
#include "io/motion_section.hpp"
#include "io/overrides.hpp"
#include "io/rheology_section.hpp"
#include "io/shape_section.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {
namespace {

const std::vector<std::string> kKernels{"cubic_spline", "hyperbolic", "wendland_c2"};

std::vector<std::string> face_names(int dimensions) {
  std::vector<std::string> names;
  for (const std::string& axis : axis_names(dimensions)) {
    names.push_back(axis + "-");
    names.push_back(axis + "+");
  }
  return names;
}

geometry::Face to_face(const std::string& name) {
  return {axis_index(name), name.back() == '+' ? 1 : -1};
}

int read_dimensions(Reader& root) {
  const int dimensions = root.required<int>("dimensions");
  if (dimensions != 2 && dimensions != 3) {
    throw root.error("dimensions", fmt::format("must be 2 or 3, got {}", dimensions));
  }
  return dimensions;
}

Domain read_domain(Reader& root, int dimensions) {
  Reader section = root.map("domain");
  Domain domain;
  domain.dimensions = dimensions;
  domain.lo = section.vector("min", dimensions);
  domain.hi = section.vector("max", dimensions);
  check_increasing(section, domain.lo, domain.hi, dimensions);
  for (const std::string& axis : section.choices("periodic", axis_names(dimensions))) {
    domain.periodic[axis_index(axis)] = true;
  }
  section.done();
  return domain;
}

TimeControl read_time(Reader& root) {
  Reader section = root.map("time");
  TimeControl time;
  time.end = section.required<double>("end", kPositive);
  time.output_interval = section.required<double>("output_interval", kPositive);
  time.sample_interval =
      section.optional<double>("sample_interval", time.output_interval, kPositive);
  section.done();
  return time;
}

sph::DensityTreatment read_density(Reader& sph_section) {
  Reader section = sph_section.optional_map("density");
  sph::DensityTreatment density;
  density.diffusion =
      section.choice("diffusion", density.diffusion, {"none", "molteni", "fourtakas"});
  density.delta = section.optional<double>("delta", density.delta, kNonNegative);
  density.shepard = section.optional<bool>("shepard", density.shepard);
  density.shepard_interval =
      section.optional<int>("shepard_interval", density.shepard_interval, at_least(1));
  section.done();
  return density;
}

sph::TimeStepFactors read_time_step(Reader& sph_section) {
  Reader section = sph_section.optional_map("time_step");
  sph::TimeStepFactors factors;
  factors.cfl = section.optional<double>("cfl", factors.cfl, kPositive);
  factors.viscous = section.optional<double>("viscous", factors.viscous, kPositive);
  factors.force = section.optional<double>("force", factors.force, kPositive);
  section.done();
  return factors;
}

std::string read_gradient_kernel(Reader& section) {
  std::vector<std::string> allowed{"same"};
  allowed.insert(allowed.end(), kKernels.begin(), kKernels.end());
  const std::string name = section.choice("gradient_kernel", "same", allowed);
  return name == "same" ? std::string() : name;
}

sph::Config read_sph(Reader& root) {
  Reader section = root.map("sph");
  sph::Config config;
  config.spacing = section.required<double>("spacing", kPositive);
  config.smoothing_ratio =
      section.optional<double>("smoothing_ratio", config.smoothing_ratio, kPositive);
  config.kernel = section.choice("kernel", config.kernel, kKernels);
  config.gradient_kernel = read_gradient_kernel(section);
  config.equation_of_state =
      section.choice("equation_of_state", config.equation_of_state, {"tait", "linear"});
  config.tait_gamma = section.optional<double>("tait_gamma", config.tait_gamma, kPositive);
  config.sound_speed = section.automatic<double>("sound_speed", kPositive);
  config.max_velocity = section.automatic<double>("max_velocity", kPositive);
  config.mach_factor = section.optional<double>("mach_factor", config.mach_factor, kPositive);
  config.artificial_viscosity =
      section.optional<double>("artificial_viscosity", config.artificial_viscosity, kNonNegative);
  config.laminar_viscosity = section.optional<bool>("laminar_viscosity", config.laminar_viscosity);
  config.viscous_operator =
      section.choice("viscous_operator", config.viscous_operator, {"auto", "morris", "stress"});
  config.viscosity_mean =
      section.choice("viscosity_mean", config.viscosity_mean, {"arithmetic", "harmonic"});
  config.corrected_velocity_gradient =
      section.choice("velocity_gradient", "corrected", {"corrected", "plain"}) == "corrected";
  config.density = read_density(section);
  config.wall_layers = section.automatic<int>("wall_layers", at_least(1));
  config.negative_wall_pressure =
      section.optional<bool>("negative_wall_pressure", config.negative_wall_pressure);
  config.time_step = read_time_step(section);
  config.sort_interval = section.optional<int>("sort_interval", config.sort_interval, at_least(1));
  section.done();
  return config;
}

std::optional<TracerPlane> read_tracer(Reader& fluid, int dimensions) {
  if (!fluid.contains("tracer"))
    return std::nullopt;
  Reader section = fluid.map("tracer");
  TracerPlane tracer;
  tracer.point = section.vector("point", dimensions, tracer.point);
  tracer.normal = section.vector("normal", dimensions, tracer.normal);
  if (tracer.normal.norm() == 0.0)
    throw section.error("normal", "the normal must not be the zero vector");
  section.done();
  return tracer;
}

FluidSpec read_fluid(Reader& root, int dimensions, const std::filesystem::path& folder) {
  Reader section = root.map("fluid");
  FluidSpec fluid;
  fluid.density = section.required<double>("density", kPositive);
  fluid.rheology = read_fluid_rheology(section);
  for (Reader& region : section.list("regions")) {
    fluid.regions.push_back({read_shape(region, dimensions, folder)});
    region.done();
  }
  fluid.tracer = read_tracer(section, dimensions);
  section.done();
  return fluid;
}

// The faces of a container wall left open; a solid wall has none, so `open` is an error there.
std::vector<geometry::Face> read_open_faces(Reader& item, int dimensions, bool solid) {
  if (solid && item.contains("open")) {
    throw item.error("open", "a solid wall (solid: true) has no open faces; remove 'open'");
  }
  std::vector<geometry::Face> faces;
  for (const std::string& face : item.choices("open", face_names(dimensions))) {
    faces.push_back(to_face(face));
  }
  return faces;
}

std::vector<WallSpec> read_walls(Reader& root, int dimensions,
                                 const std::filesystem::path& folder) {
  std::vector<WallSpec> walls;
  for (Reader& item : root.optional_list("walls")) {
    WallSpec wall{read_shape(item, dimensions, folder), {}, {}};
    wall.solid = item.optional<bool>("solid", false);
    wall.open_faces = read_open_faces(item, dimensions, wall.solid);
    wall.motion = read_motion(item, dimensions);
    item.done();
    walls.push_back(wall);
  }
  return walls;
}

OutputSpec read_output(Reader& root) {
  Reader section = root.optional_map("output");
  OutputSpec output;
  output.frames = section.optional<bool>("frames", output.frames);
  section.done();
  return output;
}

Case read_case(Reader& root, const std::string& path) {
  Case result;
  result.file = path;
  result.name = root.optional<std::string>("name", std::filesystem::path(path).stem().string());
  result.description = root.optional<std::string>("description", "");
  result.solver = root.required_choice("solver", {"sph", "dem"});
  const int dimensions = read_dimensions(root);
  if (result.solver == "dem" && dimensions != 3)
    throw root.error("dimensions", "the DEM solver needs dimensions: 3");
  result.gravity = root.vector("gravity", dimensions, Vec3::Zero());
  result.domain = read_domain(root, dimensions);
  result.time = read_time(root);
  if (result.solver == "sph") {
    result.sph = read_sph(root);
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (result.solver == "dem") {
    result.dem = read_dem(root, folder);
    result.fluid.tracer = TracerPlane{result.dem.fill.split_point, result.dem.fill.split_normal};
  } else {
    result.fluid = read_fluid(root, dimensions, folder);
    result.walls = read_walls(root, dimensions, folder);
  }
  result.output = read_output(root);
  result.analyses = read_analyses(root, dimensions, result.walls, result.fluid);
  root.done();
  return result;
}

}  // namespace

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {
  YAML::Node document = load_yaml_file(path);
  auto context = std::make_shared<ReadContext>();
  context->file = path;
  context->overridden = apply_overrides(document, overrides);
  Reader root(document, context);
  Case result = read_case(root, path);
  result.resolved = std::move(context->resolved);
  return result;
}

}  // namespace partimix::io
