#include "io/analysis_section.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/power_number.hpp"
#include "io/axis_names.hpp"
#include "io/drum_measures_section.hpp"

namespace partimix::io {
namespace {

const std::vector<std::string> kTypes{
    "front_position",    "body_loads",       "power_number",   "mixing",         "packing_fraction",
    "velocity_profile",  "angle_of_repose",  "mass_in_region", "height_profile", "mass_flux",
    "orientation_order", "drum_segregation", "drum_discharge", "droplet"};

constexpr int kMostBins = 1000;        // of a profile: one series.csv column each
constexpr double kLinkSpacings = 1.5;  // droplet: the default link distance in sph.spacing

// The corners `min` and `max` of an axis-aligned box, max > min along every axis.
void read_box(Reader& reader, int dimensions, Vec3& lo, Vec3& hi) {
  lo = reader.vector("min", dimensions);
  hi = reader.vector("max", dimensions);
  for (int k = 0; k < dimensions; ++k) {
    if (!(hi[k] > lo[k]))
      throw reader.error("max", "max must exceed min along every axis");
  }
}

// Refuses a profile of more than kMostBins bins.
void check_bins(Reader& item, int bins) {
  if (bins > kMostBins)
    throw item.error("bins", fmt::format("at most {} bins", kMostBins));
}

// body, vessel_axis_point and average_revolutions of body_loads and power_number.
void read_body(Reader& item, AnalysisSpec& analysis, int dimensions,
               const std::vector<WallSpec>& walls) {
  analysis.body = item.required<int>("body", at_least(0));
  if (static_cast<std::size_t>(analysis.body) >= walls.size()) {
    throw item.error("body", fmt::format("there is no wall {} (the case has {} walls, counted "
                                         "from 0)",
                                         analysis.body, walls.size()));
  }
  const geometry::MotionConfig& motion = walls[static_cast<std::size_t>(analysis.body)].motion;
  const Vec3 default_point = motion.type == "planetary" ? motion.centre : Vec3::Zero();
  analysis.vessel_axis_point = item.vector("vessel_axis_point", dimensions, default_point);
  analysis.average_revolutions =
      item.optional<double>("average_revolutions", analysis.average_revolutions, kPositive);
}

void read_power_number(Reader& item, AnalysisSpec& analysis, const Case& the_case,
                       const MethodSection& section) {
  analysis.diameter = item.required<double>("diameter", kPositive);
  analysis.metzner_otto = item.optional<double>("metzner_otto", analysis.metzner_otto, kPositive);
  if (!section.flow_scales()) {
    throw item.error("type", fmt::format("power numbers need a newtonian, power_law or "
                                         "herschel_bulkley fluid (Re by eq. 27 needs K and n); "
                                         "method {} has none",
                                         analysis.method));
  }
  try {
    analysis::power_scales(the_case.walls[static_cast<std::size_t>(analysis.body)].motion,
                           analysis.diameter);
  } catch (const std::invalid_argument& error) {
    throw item.error("body", fmt::format("wall {}: {}", analysis.body, error.what()));
  }
}

std::array<int, 3> read_cells(Reader& item, int count) {
  const Vec3 cells = item.vector("cells", count);
  constexpr double kMostCells = 1.0e7;  // in all, so that the counts stay small ints
  std::array<int, 3> result{1, 1, 1};
  double total = 1.0;
  for (int k = 0; k < count; ++k) {
    if (cells[k] < 1.0 || cells[k] != std::floor(cells[k]))
      throw item.error("cells", "cell counts must be whole numbers of at least 1");
    total *= cells[k];
    if (total > kMostCells)
      throw item.error("cells", fmt::format("at most {:g} cells in all", kMostCells));
    result[static_cast<std::size_t>(k)] = static_cast<int>(cells[k]);
  }
  return result;
}

// A cylinder about `axis` through `axis_point`: radius, the axial span [bottom, top] measured
// from axis_point, cells [rings, sectors, layers]; in 2D a disc, cells [rings, sectors].
void read_cylinder_region(Reader& item, analysis::MixingRegion& region, int dimensions) {
  analysis::CylinderRegion& cylinder = region.cylinder_region;
  cylinder.axis_point = item.vector("axis_point", dimensions, Vec3::Zero());
  cylinder.radius = item.required<double>("radius", kPositive);
  if (dimensions == 3) {
    cylinder.axis = item.vector("axis", 3, Vec3::UnitZ());
    if (cylinder.axis.norm() == 0.0)
      throw item.error("axis", "the axis must not be the zero vector");
    cylinder.z0 = item.required<double>("bottom");
    cylinder.z1 = item.required<double>("top");
    if (!(cylinder.z1 > cylinder.z0))
      throw item.error("top", "top must lie above bottom");
  } else {
    cylinder.z0 = -1.0;
    cylinder.z1 = 1.0;
  }
  region.cells = read_cells(item, dimensions);
}

void read_box_region(Reader& item, analysis::MixingRegion& region, int dimensions) {
  region.cylinder = false;
  read_box(item, dimensions, region.lo, region.hi);
  region.cells = read_cells(item, dimensions);
}

void read_mixing(Reader& item, AnalysisSpec& analysis, int dimensions,
                 const MethodSection& section) {
  if (!section.has_tracer()) {
    throw item.error("type", fmt::format("a mixing analysis needs a tracer in the material of "
                                         "method {} (fluid.tracer for sph, two species for dem)",
                                         analysis.method));
  }
  analysis::MixingRegion& region = analysis.mixing;
  if (item.choice("region", "cylinder", {"cylinder", "box"}) == "cylinder")
    read_cylinder_region(item, region, dimensions);
  else
    read_box_region(item, region, dimensions);
  region.min_count = item.optional<int>("min_count", region.min_count, at_least(1));
}

// packing_fraction: the box [min, max].
void read_packing_fraction(Reader& item, AnalysisSpec& analysis, int dimensions) {
  read_box(item, dimensions, analysis.packing.lo, analysis.packing.hi);
}

// velocity_profile: the segment [start, end], bins, width and the component (a direction or the
// word speed).
void read_velocity_profile(Reader& item, AnalysisSpec& analysis, int dimensions) {
  analysis::ProfileLine& line = analysis.profile;
  line.start = item.vector("start", dimensions);
  line.end = item.vector("end", dimensions);
  if (line.end == line.start)
    throw item.error("end", "end must differ from start");
  line.bins = item.optional<int>("bins", line.bins, at_least(1));
  check_bins(item, line.bins);
  line.width = item.required<double>("width", kPositive);
  const std::string expected = fmt::format(
      "expected the word speed or a direction (a list of {} numbers, not all zero)", dimensions);
  try {
    item.choice("component", "speed", {"speed"});  // absent: the speed
    line.speed = true;
    return;
  } catch (const InputError&) {
    // not the word speed: a direction, or an error
  }
  try {
    line.direction = item.vector("component", dimensions);
  } catch (const InputError&) {
    throw item.error("component", expected);
  }
  if (line.direction.norm() == 0.0)
    throw item.error("component", expected);
  line.speed = false;
  line.direction.normalize();
}

// angle_of_repose: the drum axis (3D; z in 2D) through centre, gravity's direction, bins, trim.
void read_angle_of_repose(Reader& item, AnalysisSpec& analysis, int dimensions) {
  analysis::ReposeSection& section = analysis.repose;
  if (dimensions == 3) {
    section.axis = item.vector("axis", 3, Vec3::UnitZ());
    if (section.axis.norm() == 0.0)
      throw item.error("axis", "the axis must not be the zero vector");
  }
  section.centre = item.vector("centre", dimensions, Vec3::Zero());
  section.down = item.vector("down", dimensions, -Vec3::UnitY());
  const Vec3 axis = section.axis.normalized();
  const Vec3 normal_part = section.down - section.down.dot(axis) * axis;
  if (!(normal_part.norm() > 1.0e-9 * section.down.norm()))
    throw item.error("down", "down must not be zero or parallel to the axis");
  section.bins = item.optional<int>("bins", section.bins, at_least(2));
  section.trim = item.optional<double>("trim", section.trim, kNonNegative);
  if (!(section.trim < 0.5))
    throw item.error("trim", "trim must be below 0.5 (it is dropped at each end)");
}

// mass_in_region: the box `region: {min, max}` and the fit window [fit_from, fit_until] (no end
// for `auto`).
void read_mass_in_region(Reader& item, AnalysisSpec& analysis, int dimensions) {
  analysis::MassRegion& region = analysis.region_mass;
  Reader box = item.map("region");
  read_box(box, dimensions, region.lo, region.hi);
  box.done();
  region.fit_from = item.optional<double>("fit_from", region.fit_from, kNonNegative);
  if (const std::optional<double> until = item.automatic<double>("fit_until", kPositive)) {
    if (!(*until > region.fit_from))
      throw item.error("fit_until", "fit_until must be later than fit_from");
    region.fit_until = *until;
  }
}

// mass_flux: the plane (`point`, `normal`), the band's `width` and `average_from`.
void read_mass_flux(Reader& item, AnalysisSpec& analysis, int dimensions) {
  analysis::FluxPlane& plane = analysis.flux;
  plane.point = item.vector("point", dimensions);
  const Vec3 normal = item.vector("normal", dimensions);
  if (!(normal.norm() > 0.0))
    throw item.error("normal", "normal must not be zero");
  plane.normal = normal.normalized();
  plane.width = item.required<double>("width", kPositive);
  plane.average_from = item.optional<double>("average_from", 0.0, kNonNegative);
}

// height_profile: the binned axis, the vertical axis, the span [from, to] and the bins.
void read_height_profile(Reader& item, AnalysisSpec& analysis, int dimensions) {
  analysis::HeightLine& line = analysis.height;
  line.axis = axis_index(item.required_choice("axis", axis_names(dimensions)));
  line.vertical = axis_index(item.required_choice("vertical", axis_names(dimensions)));
  if (line.vertical == line.axis)
    throw item.error("vertical", "vertical must differ from axis");
  line.from = item.required<double>("from");
  line.to = item.required<double>("to");
  if (!(line.to > line.from))
    throw item.error("to", "to must exceed from");
  line.bins = item.required<int>("bins", at_least(1));
  check_bins(item, line.bins);
}

// orientation_order's rotating_frame: {axis_point, axis, rpm}, a frame turning as a drum does
// (the right-hand rule about the axis for rpm > 0); velocities are taken relative to it.
void read_rotating_frame(Reader& item, analysis::OrientationReference& reference, int dimensions) {
  Reader frame = item.map("rotating_frame");
  reference.frame_point = frame.vector("axis_point", dimensions);
  const Vec3 axis = frame.vector("axis", 3);
  if (!(axis.norm() > 0.0) || !axis.allFinite())
    throw frame.error("axis", "expected a direction (3 numbers, not all zero)");
  const double rpm = frame.required<double>("rpm");
  if (!std::isfinite(rpm))
    throw frame.error("rpm", "expected a finite number");
  frame.done();
  reference.rotating_frame = true;
  reference.frame_angular_velocity = (2.0 * std::numbers::pi * rpm / 60.0) * axis.normalized();
}

// orientation_order: the reference direction (the word velocity, the default, or a direction)
// and, with the velocity, min_speed and rotating_frame. Refused for a method without grains that
// have an axis.
void read_orientation_order(Reader& item, AnalysisSpec& analysis, int dimensions,
                            const MethodSection& section) {
  if (!section.has_grain_axes()) {
    throw item.error("type", fmt::format("the orientation order needs grains with an axis: a dem "
                                         "species whose shape has unequal half-axes "
                                         "(spheres have none); method {} has none",
                                         analysis.method));
  }
  analysis::OrientationReference& reference = analysis.orientation;
  reference.velocity = true;
  try {
    item.choice("direction", "velocity", {"velocity"});  // absent: the velocity
  } catch (const InputError&) {
    reference.velocity = false;  // not the word velocity: a direction, or an error
  }
  if (reference.velocity) {
    reference.min_speed = item.optional<double>("min_speed", 0.0, kNonNegative);
    if (item.contains("rotating_frame"))
      read_rotating_frame(item, reference, dimensions);
    return;
  }
  const std::string expected = fmt::format(
      "expected the word velocity or a direction (a list of {} numbers, not all zero)", dimensions);
  try {
    reference.direction = item.vector("direction", dimensions);
  } catch (const InputError&) {
    throw item.error("direction", expected);
  }
  if (!(reference.direction.norm() > 0.0))
    throw item.error("direction", expected);
  for (const char* key : {"min_speed", "rotating_frame"}) {
    if (item.contains(key))
      throw item.error(key, "applies with direction: velocity only");
  }
  reference.direction.normalize();
}

// droplet: `shell` and `gas`, names from sph.materials (the shell's not among the gases), and
// `link` (1.5 sph.spacing by default) and `after_rupture` (0.1 s). Refused for a method without
// materials (an SPH scheme other than multi_material, or another method).
void read_droplet(Reader& item, AnalysisSpec& analysis, const Case& the_case,
                  const MethodSection& section) {
  const std::vector<std::string> names = section.material_names();
  if (names.empty()) {
    throw item.error("type", fmt::format("the droplet analysis needs sph.scheme: multi_material, "
                                         "whose sph.materials name the shell and the gas; "
                                         "method {} has no materials",
                                         analysis.method));
  }
  const auto index_of = [&names](const std::string& name) {
    return static_cast<int>(std::ranges::find(names, name) - names.begin());
  };
  analysis::DropletOptions& droplet = analysis.droplet;
  droplet.shell = index_of(item.required_choice("shell", names));
  droplet.gas.clear();
  for (const std::string& gas : item.required_choices("gas", names)) {
    if (index_of(gas) == droplet.shell)
      throw item.error("gas", fmt::format("'{}' is the shell's material, not a gas", gas));
    droplet.gas.push_back(index_of(gas));
  }
  const std::optional<double> spacing = section.spacing();
  droplet.link = spacing ? item.optional<double>("link", kLinkSpacings * *spacing, kPositive)
                         : item.required<double>("link", kPositive);
  droplet.after_rupture = item.optional<double>("after_rupture", 0.1, kPositive);
  droplet.dimensions = the_case.domain.dimensions;
}

// The method whose particles the analysis measures: `method`, by default the first of the case.
const MethodSection& read_method(Reader& item, AnalysisSpec& analysis, const Case& the_case) {
  std::vector<std::string> names;
  for (const MethodSpec& spec : the_case.methods)
    names.push_back(spec.name);
  analysis.method = item.choice("method", names.front(), names);
  return *the_case.method(analysis.method)->section;
}

// `name`: letters, digits and '_' only, so that "<name>.<column>" stays one CSV field.
std::string read_name(Reader& item) {
  const std::string name = item.optional<std::string>("name", "");
  const auto allowed = [](unsigned char c) { return std::isalnum(c) != 0 || c == '_'; };
  if (!std::all_of(name.begin(), name.end(), allowed))
    throw item.error("name", "a name holds letters, digits and '_' only, got '" + name + "'");
  return name;
}

// sample_interval, sample_from, sample_until: an analysis sampled on its own schedule into
// series_<name>.csv (a short impact sampled finely inside a long run).
void read_schedule(Reader& item, AnalysisSpec& analysis, const Case& the_case) {
  analysis.sample_interval = item.automatic<double>("sample_interval", kPositive);
  if (!analysis.sample_interval) {
    for (const std::string key : {"sample_from", "sample_until"}) {
      if (item.contains(key))
        throw item.error(key, "applies with the analysis' own sample_interval only");
    }
    return;
  }
  if (analysis.name.empty()) {
    throw item.error("sample_interval",
                     "an analysis with its own sample_interval needs a "
                     "`name`: its rows go to series_<name>.csv");
  }
  analysis.sample_from = item.optional<double>("sample_from", 0.0, kNonNegative);
  // `auto` (the default): to the end of the run, whatever time.end a resumed run is given.
  if (const std::optional<double> until = item.automatic<double>("sample_until", kPositive))
    analysis.sample_until = *until;
  if (!(analysis.sample_until > analysis.sample_from))
    throw item.error("sample_until", "must be later than sample_from");
  const double span = std::min(analysis.sample_until, the_case.time.end) - analysis.sample_from;
  const double rows = span / *analysis.sample_interval;
  if (rows > the_case.limits.series_rows) {
    throw item.error("sample_interval",
                     fmt::format("{:.3g} rows, more than limits.series_rows = {:.3g}; lengthen "
                                 "the interval, shorten the span or raise the limit",
                                 rows, the_case.limits.series_rows));
  }
}

// The keys of the analysis' own type.
void read_type_keys(Reader& item, AnalysisSpec& analysis, const Case& the_case,
                    const MethodSection& section) {
  const int dimensions = the_case.domain.dimensions;
  if (analysis.type == "front_position")
    analysis.axis = axis_index(item.choice("axis", "x", axis_names(dimensions)));
  if (analysis.type == "body_loads" || analysis.type == "power_number")
    read_body(item, analysis, dimensions, the_case.walls);
  if (analysis.type == "power_number")
    read_power_number(item, analysis, the_case, section);
  if (analysis.type == "mixing")
    read_mixing(item, analysis, dimensions, section);
  if (analysis.type == "packing_fraction")
    read_packing_fraction(item, analysis, dimensions);
  if (analysis.type == "velocity_profile")
    read_velocity_profile(item, analysis, dimensions);
  if (analysis.type == "angle_of_repose")
    read_angle_of_repose(item, analysis, dimensions);
  if (analysis.type == "mass_in_region")
    read_mass_in_region(item, analysis, dimensions);
  if (analysis.type == "mass_flux")
    read_mass_flux(item, analysis, dimensions);
  if (analysis.type == "height_profile")
    read_height_profile(item, analysis, dimensions);
  if (analysis.type == "orientation_order")
    read_orientation_order(item, analysis, dimensions, section);
  if (analysis.type == "drum_segregation" || analysis.type == "drum_discharge")
    read_drum_measures(item, analysis, the_case);
  if (analysis.type == "droplet")
    read_droplet(item, analysis, the_case, section);
}

}  // namespace

std::vector<AnalysisSpec> read_analyses(Reader& root, const Case& the_case) {
  std::vector<AnalysisSpec> analyses;
  for (Reader& item : root.optional_list("analyses")) {
    AnalysisSpec analysis;
    analysis.key = fmt::format("analyses[{}]", analyses.size());
    analysis.type = item.required_choice("type", kTypes);
    analysis.name = read_name(item);
    for (const AnalysisSpec& earlier : analyses) {
      if (!analysis.name.empty() && earlier.name == analysis.name) {
        throw item.error("name", fmt::format("{} has this name already: names are the prefixes "
                                             "of columns and of series files",
                                             earlier.key));
      }
    }
    read_schedule(item, analysis, the_case);
    read_type_keys(item, analysis, the_case, read_method(item, analysis, the_case));
    item.done();
    analyses.push_back(analysis);
  }
  return analyses;
}

}  // namespace partimix::io
