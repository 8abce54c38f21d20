#include "io/analysis_section.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/power_number.hpp"
#include "io/axis_names.hpp"

namespace partimix::io {
namespace {

const std::vector<std::string> kTypes{"front_position", "body_loads", "power_number", "mixing"};

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

void check_flow_scales(Reader& item, const FluidSpec& fluid) {
  const std::string& model = fluid.rheology.model;
  if (model != "newtonian" && model != "power_law" && model != "herschel_bulkley") {
    throw item.error("type",
                     "power numbers need a newtonian, power_law or herschel_bulkley "
                     "fluid (Re by eq. 27 needs K and n); the fluid is " +
                         model);
  }
}

void read_power_number(Reader& item, AnalysisSpec& analysis, const std::vector<WallSpec>& walls,
                       const FluidSpec& fluid) {
  analysis.diameter = item.required<double>("diameter", kPositive);
  analysis.metzner_otto = item.optional<double>("metzner_otto", analysis.metzner_otto, kPositive);
  check_flow_scales(item, fluid);
  try {
    analysis::power_scales(walls[static_cast<std::size_t>(analysis.body)].motion,
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
  region.lo = item.vector("min", dimensions);
  region.hi = item.vector("max", dimensions);
  for (int k = 0; k < dimensions; ++k) {
    if (!(region.hi[k] > region.lo[k]))
      throw item.error("max", "max must exceed min along every axis");
  }
  region.cells = read_cells(item, dimensions);
}

void read_mixing(Reader& item, AnalysisSpec& analysis, int dimensions, const FluidSpec& fluid) {
  if (!fluid.tracer)
    throw item.error("type", "a mixing analysis needs fluid.tracer (which fluid is the tracer)");
  analysis::MixingRegion& region = analysis.mixing;
  if (item.choice("region", "cylinder", {"cylinder", "box"}) == "cylinder")
    read_cylinder_region(item, region, dimensions);
  else
    read_box_region(item, region, dimensions);
  region.min_count = item.optional<int>("min_count", region.min_count, at_least(1));
}

}  // namespace

std::vector<AnalysisSpec> read_analyses(Reader& root, int dimensions,
                                        const std::vector<WallSpec>& walls,
                                        const FluidSpec& fluid) {
  std::vector<AnalysisSpec> analyses;
  for (Reader& item : root.optional_list("analyses")) {
    AnalysisSpec analysis;
    analysis.type = item.required_choice("type", kTypes);
    if (analysis.type == "front_position")
      analysis.axis = axis_index(item.choice("axis", "x", axis_names(dimensions)));
    if (analysis.type == "body_loads" || analysis.type == "power_number")
      read_body(item, analysis, dimensions, walls);
    if (analysis.type == "power_number")
      read_power_number(item, analysis, walls, fluid);
    if (analysis.type == "mixing")
      read_mixing(item, analysis, dimensions, fluid);
    item.done();
    analyses.push_back(analysis);
  }
  return analyses;
}

}  // namespace partimix::io
