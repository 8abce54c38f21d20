#include "sph/sph_section.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "io/rheology_section.hpp"
#include "io/shape_section.hpp"
#include "sph/multi_material/materials_section.hpp"

namespace partimix::sph {
namespace {

using io::at_least;
using io::kNonNegative;
using io::kPositive;
using io::Reader;

const std::vector<std::string> kKernels{"cubic_spline", "hyperbolic", "wendland_c2"};
const std::string kMultiMaterial = "multi_material";

DensityTreatment read_density(Reader& sph_section) {
  Reader section = sph_section.optional_map("density");
  DensityTreatment density;
  density.diffusion =
      section.choice("diffusion", density.diffusion, {"none", "molteni", "fourtakas"});
  density.delta = section.optional<double>("delta", density.delta, kNonNegative);
  density.shepard = section.optional<bool>("shepard", density.shepard);
  density.shepard_interval =
      section.optional<int>("shepard_interval", density.shepard_interval, at_least(1));
  section.done();
  return density;
}

Shifting read_shifting(Reader& sph_section) {
  Reader section = sph_section.optional_map("shifting");
  Shifting shifting;
  shifting.model = section.choice("model", shifting.model, {"none", "fickian"});
  shifting.coefficient = section.optional<double>("coefficient", shifting.coefficient, kPositive);
  section.done();
  return shifting;
}

TimeStepFactors read_time_step(Reader& sph_section) {
  Reader section = sph_section.optional_map("time_step");
  TimeStepFactors factors;
  factors.cfl = section.optional<double>("cfl", factors.cfl, kPositive);
  factors.flow_cfl = section.optional<double>("flow_cfl", factors.flow_cfl, kPositive);
  factors.viscous = section.optional<double>("viscous", factors.viscous, kPositive);
  factors.force = section.optional<double>("force", factors.force, kPositive);
  factors.conductive = section.optional<double>("conductive", factors.conductive, kPositive);
  factors.capillary = section.optional<double>("capillary", factors.capillary, kPositive);
  section.done();
  return factors;
}

std::string read_gradient_kernel(Reader& section) {
  std::vector<std::string> allowed{"same"};
  allowed.insert(allowed.end(), kKernels.begin(), kKernels.end());
  const std::string name = section.choice("gradient_kernel", "same", allowed);
  return name == "same" ? std::string() : name;
}

// `lattice`: {type: cartesian} (the default), or {type: polar, centre, rings} for rings about
// the centre's z-parallel axis, `rings` staggered (the default) or golden; not along a periodic
// x or y (the rings would not repeat).
void read_lattice(Reader& sph, const Domain& domain, Config& config) {
  Reader section = sph.optional_map("lattice");
  if (section.choice("type", "cartesian", {"cartesian", "polar"}) == "cartesian") {
    section.done();
    return;
  }
  config.polar_centre = section.vector("centre", domain.dimensions);
  config.golden_rings = section.choice("rings", "staggered", {"staggered", "golden"}) == "golden";
  section.done();
  if (domain.periodic[0] || domain.periodic[1])
    throw sph.error("lattice", "a polar lattice cannot repeat along a periodic x or y axis");
}

// `materials` and `multi_material` belong to scheme: multi_material alone.
MultiMaterialSettings read_scheme_materials(Reader& sph, const std::string& scheme) {
  if (scheme == kMultiMaterial) {
    return read_multi_material(sph);
  }
  for (const std::string key : {"materials", "multi_material"}) {
    if (sph.contains(key)) {
      throw sph.error(key,
                      fmt::format("only with scheme: multi_material (the scheme is {})", scheme));
    }
  }
  return {};
}

// sph.smoothing_length: constant (the default) or variable, with the weakly-compressible scheme
// alone: the incompressible one keeps rho = rho0, the multi-material one always varies h
// (docs/sph.md, "Variable smoothing length").
bool read_smoothing_length(Reader& sph, const std::string& scheme) {
  const bool variable =
      sph.choice("smoothing_length", "constant", {"constant", "variable"}) == "variable";
  if (variable && scheme == "incompressible") {
    throw sph.error("smoothing_length",
                    "the incompressible scheme keeps the density at rho0, so h cannot vary");
  }
  if (sph.contains("smoothing_length") && scheme == kMultiMaterial) {
    throw sph.error("smoothing_length",
                    "scheme: multi_material always varies h with the density "
                    "(sph.multi_material.density)");
  }
  return variable;
}

Config read_config(Reader& root, const Domain& domain) {
  Reader section = root.map("sph");
  Config config;
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
  config.flow_length = section.automatic<double>("flow_length", kPositive);
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
  config.shifting = read_shifting(section);
  config.wall_layers = section.automatic<int>("wall_layers", at_least(1));
  config.negative_wall_pressure =
      section.optional<bool>("negative_wall_pressure", config.negative_wall_pressure);
  config.wall_velocity =
      section.choice("wall_velocity", config.wall_velocity, {"adami", "extrapolated"});
  config.time_step = read_time_step(section);
  config.sort_interval = section.optional<int>("sort_interval", config.sort_interval, at_least(1));
  read_lattice(section, domain, config);
  config.scheme = section.choice("scheme", config.scheme,
                                 {"weakly_compressible", "incompressible", kMultiMaterial});
  config.pressure_tolerance =
      section.optional<double>("pressure_tolerance", config.pressure_tolerance, kPositive);
  config.pressure_iterations =
      section.optional<int>("pressure_iterations", config.pressure_iterations, at_least(1));
  config.viscosity_integration = section.choice(
      "viscosity_integration", config.viscosity_integration, {"explicit", "implicit"});
  config.viscosity_iterations =
      section.optional<int>("viscosity_iterations", config.viscosity_iterations, at_least(1));
  config.multi_material = read_scheme_materials(section, config.scheme);
  config.variable_smoothing_length = read_smoothing_length(section, config.scheme);
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

// With scheme: multi_material each material has its own density and viscosity, so the fluid
// has none.
void reject_fluid_properties(const Reader& fluid) {
  for (const std::string key : {"density", "viscosity", "rheology"}) {
    if (fluid.contains(key)) {
      throw fluid.error(key,
                        "not with sph.scheme: multi_material, where each of sph.materials "
                        "has its own density and viscosity");
    }
  }
}

// The index in sph.materials of the region's `material`, which only scheme: multi_material has.
int read_material_index(Reader& region, const Config& config) {
  if (config.scheme == kMultiMaterial) {
    return read_region_material(region, config.multi_material.materials);
  }
  if (region.contains("material")) {
    throw region.error(
        "material", "only with sph.scheme: multi_material (the scheme is " + config.scheme + ")");
  }
  return -1;
}

FluidSpec read_fluid(Reader& root, const Config& config, int dimensions,
                     const std::filesystem::path& folder) {
  Reader section = root.map("fluid");
  FluidSpec fluid;
  if (config.scheme == kMultiMaterial) {
    reject_fluid_properties(section);
  } else {
    fluid.density = section.required<double>("density", kPositive);
    fluid.rheology = io::read_fluid_rheology(section);
  }
  for (Reader& region : section.list("regions")) {
    fluid.regions.push_back(
        {io::read_shape(region, dimensions, folder), read_material_index(region, config)});
    region.done();
  }
  fluid.tracer = read_tracer(section, dimensions);
  section.done();
  return fluid;
}

// SPH lays particles from each wall's shape, which a mesh that is not closed does not have.
void require_shapes(const io::Case& the_case) {
  for (const io::WallSpec& wall : the_case.walls) {
    if (wall.no_shape) {
      throw InputError(wall.no_shape->location(),
                       wall.no_shape->message() + "; SPH lays wall particles from a closed mesh");
    }
  }
}

}  // namespace

std::shared_ptr<SphSection> read_sph_section(Reader& root, const io::Case& the_case) {
  require_shapes(the_case);
  auto section = std::make_shared<SphSection>();
  section->config = read_config(root, the_case.domain);
  const std::filesystem::path folder = std::filesystem::path(the_case.file).parent_path();
  section->fluid = read_fluid(root, section->config, the_case.domain.dimensions, folder);
  return section;
}

}  // namespace partimix::sph
