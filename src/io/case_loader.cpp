// load_case: the case-file schema, section by section, in the order of
// docs/case-reference.md. Each section reads its keys through a Reader and ends with done(),
// which rejects the keys it did not ask for. The shared sections come first; then each method
// of `solver` reads its own (io/method_type.hpp).
#include <filesystem>

#include <fmt/format.h>

#include "io/analysis_section.hpp"
#include "io/axis_names.hpp"
#include "io/case.hpp"
#include "io/coupling_type.hpp"
#include "io/method_type.hpp"
#include "io/overrides.hpp"
#include "io/shape_section.hpp"
#include "io/walls_section.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {
namespace {

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

// sub_steps: per method, the steps it takes per step of the run's clock (default 1).
void read_sub_steps(Reader& time, std::vector<MethodSpec>& methods) {
  Reader section = time.optional_map("sub_steps");
  for (MethodSpec& method : methods)
    method.sub_steps = section.optional<int>(method.name, 1, at_least(1));
  section.done();
}

SizeLimits read_limits(Reader& root) {
  Reader section = root.optional_map("limits");
  SizeLimits limits;
  limits.particles = section.optional<double>("particles", limits.particles, at_least(1.0));
  limits.lattice_points =
      section.optional<double>("lattice_points", limits.lattice_points, at_least(1.0));
  limits.steps = section.optional<double>("steps", limits.steps, at_least(1.0));
  limits.series_rows = section.optional<double>("series_rows", limits.series_rows, at_least(1.0));
  limits.frames = section.optional<double>("frames", limits.frames, at_least(1.0));
  limits.grid_nodes = section.optional<double>("grid_nodes", limits.grid_nodes, at_least(1.0));
  section.done();
  return limits;
}

// An interval of `time` at `key` that would make more than `limit` of `what` by the end.
void check_count(Reader& time, const std::string& key, double end, double interval,
                 const std::string& what, double limit, const std::string& limit_key) {
  const double count = end / interval;
  if (count > limit) {
    throw time.error(key, fmt::format("an interval of {:.3g} s up to time.end = {:.6g} s makes "
                                      "{:.3g} {}, more than {} = {:.3g}; lengthen the interval "
                                      "or raise {}",
                                      interval, end, count, what, limit_key, limit, limit_key));
  }
}

TimeControl read_time(Reader& root, std::vector<MethodSpec>& methods, const SizeLimits& limits) {
  Reader section = root.map("time");
  TimeControl time;
  time.end = section.required<double>("end", kPositive);
  time.output_interval = section.required<double>("output_interval", kPositive);
  time.sample_interval =
      section.optional<double>("sample_interval", time.output_interval, kPositive);
  time.checkpoint_interval = section.optional<double>("checkpoint_interval", 0.0, kNonNegative);
  time.fixed_dt = section.automatic<double>("dt", kPositive);
  check_count(section, "output_interval", time.end, time.output_interval, "frames", limits.frames,
              "limits.frames");
  check_count(section, "sample_interval", time.end, time.sample_interval, "series rows",
              limits.series_rows, "limits.series_rows");
  if (time.checkpoint_interval > 0.0) {
    check_count(section, "checkpoint_interval", time.end, time.checkpoint_interval, "checkpoints",
                limits.frames, "limits.frames");
  }
  if (time.fixed_dt) {
    check_count(section, "dt", time.end, *time.fixed_dt, "steps", limits.steps, "limits.steps");
  }
  read_sub_steps(section, methods);
  section.done();
  return time;
}

OutputSpec read_output(Reader& root) {
  Reader section = root.optional_map("output");
  OutputSpec output;
  output.frames = section.optional<bool>("frames", output.frames);
  section.done();
  return output;
}

std::vector<MethodSpec> read_methods(Reader& root) {
  std::vector<MethodSpec> methods;
  for (const std::string& name : root.required_choices("solver", method_registry().names()))
    methods.push_back({name, nullptr, 1});
  return methods;
}

// Each method reads its own sections, after the shared ones it may look at.
void read_method_sections(Reader& root, Case& the_case) {
  for (MethodSpec& method : the_case.methods)
    method.section = method_registry().create(method.name)->read(root, the_case);
}

// The couplings, each read by its type after the methods' sections.
void read_couplings(Reader& root, Case& the_case) {
  std::vector<Reader> items = root.optional_list("couplings");
  for (std::size_t k = 0; k < items.size(); ++k) {
    Reader& item = items[k];
    CouplingSpec spec;
    spec.type = item.required_choice("type", coupling_registry().names());
    spec.key = fmt::format("couplings[{}]", k);
    spec.section = coupling_registry().create(spec.type)->read(item, the_case);
    item.done();
    the_case.couplings.push_back(std::move(spec));
  }
}

Case read_case(Reader& root, const std::string& path) {
  Case result;
  result.file = path;
  result.name = root.optional<std::string>("name", std::filesystem::path(path).stem().string());
  result.description = root.optional<std::string>("description", "");
  result.methods = read_methods(root);
  const int dimensions = read_dimensions(root);
  result.gravity = root.vector("gravity", dimensions, Vec3::Zero());
  result.domain = read_domain(root, dimensions);
  result.limits = read_limits(root);
  result.time = read_time(root, result.methods, result.limits);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  result.walls = read_walls(root, dimensions, folder);
  read_method_sections(root, result);
  read_couplings(root, result);
  result.output = read_output(root);
  result.analyses = read_analyses(root, result);
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
  result.key_locations = std::move(context->locations);
  return result;
}

}  // namespace partimix::io

namespace partimix::io {

InputLocation Case::locate(const std::string& key_path) const {
  for (std::string path = key_path; !path.empty();) {
    if (const auto found = key_locations.find(path); found != key_locations.end()) {
      InputLocation location = found->second;
      location.key_path = key_path;
      return location;
    }
    const std::size_t cut = path.find_last_of(".[");
    path.resize(cut == std::string::npos ? 0 : cut);
  }
  return {file, 0, 0, key_path};
}

const MethodSpec* Case::method(const std::string& method_name) const {
  for (const MethodSpec& spec : methods) {
    if (spec.name == method_name)
      return &spec;
  }
  return nullptr;
}

}  // namespace partimix::io
