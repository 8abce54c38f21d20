#include "app/method_outputs.hpp"

#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kinetic_energy.hpp"
#include "analysis/max_speed.hpp"
#include "core/error.hpp"
#include "io/vti_frame_writer.hpp"
#include "io/vtk_frame_writer.hpp"

namespace partimix::app {
namespace {

analysis::AnalysisOptions options_of(const io::AnalysisSpec& spec, const io::Case& the_case,
                                     const io::MethodSection& section,
                                     const geometry::MovingBodies* bodies) {
  analysis::AnalysisOptions options;
  options.axis = spec.axis;
  options.diameter = spec.diameter;
  options.metzner_otto = spec.metzner_otto;
  options.fluid = section.flow_scales().value_or(analysis::FlowScales{});
  options.mixing = spec.mixing;
  options.packing = spec.packing;
  options.profile = spec.profile;
  options.repose = spec.repose;
  options.region_mass = spec.region_mass;
  options.flux = spec.flux;
  options.height = spec.height;
  options.orientation = spec.orientation;
  options.drum_measures = spec.drum_measures;
  options.droplet = spec.droplet;
  if (spec.type == "body_loads" || spec.type == "power_number") {
    if (bodies == nullptr || static_cast<std::size_t>(spec.body) >= bodies->count()) {
      throw InputError(the_case.locate(spec.key + ".body"),
                       fmt::format("the analysis '{}' needs wall {} as a body of method {}, "
                                   "which has no such body",
                                   spec.type, spec.body, spec.method));
    }
    const auto body = static_cast<std::size_t>(spec.body);
    options.body = {spec.body, &bodies->motion(body), the_case.walls[body].motion,
                    spec.vessel_axis_point, spec.average_revolutions};
  }
  return options;
}

// The analysis of `spec`; an option its constructor refuses (std::invalid_argument, e.g. a
// profile line of zero length) is an InputError at the analysis' key, never an abort.
std::unique_ptr<analysis::Analysis> create_analysis(const io::AnalysisSpec& spec,
                                                    const io::Case& the_case,
                                                    const io::MethodSection& section,
                                                    const geometry::MovingBodies* bodies) {
  const analysis::AnalysisOptions options = options_of(spec, the_case, section, bodies);
  try {
    return analysis::analysis_registry().create(spec.type, options);
  } catch (const std::invalid_argument& error) {
    throw InputError(the_case.locate(spec.key), error.what());
  }
}

}  // namespace

// Kinetic energy reads the particle fields at set-up: its rotational column exists only for
// particles with angular velocities and radii (DEM).
MethodOutputs::MethodOutputs(const io::Case& the_case, std::size_t m,
                             const io::MethodInstance& method)
    : name_(the_case.methods[m].name),
      method_(method),
      frame_extension_(method.solver->grid_frame() != nullptr ? "vti" : "vtp") {
  analyses_.push_back(std::make_unique<analysis::KineticEnergy>(*method.store));
  analyses_.push_back(std::make_unique<analysis::MaxSpeed>());
  prefixes_.assign(2, "");
  specs_.assign(2, nullptr);
  std::map<std::string, std::string> writer_of;  // column -> key of the analysis writing it
  const auto claim = [&](const std::string& key, const analysis::Analysis& a,
                         const std::string& prefix) {
    for (const analysis::Column& column : a.columns()) {
      const auto [at, fresh] = writer_of.emplace(prefix + column.name, key);
      if (!fresh) {
        throw InputError(the_case.locate(key),
                         fmt::format("its series column '{}' is already written by {}; give "
                                     "the analyses distinct `name`s",
                                     at->first, at->second));
      }
    }
  };
  for (std::size_t k = 0; k < analyses_.size(); ++k)
    claim("the built-in analyses", *analyses_[k], "");
  load_caveats_.assign(analyses_.size(), "");
  const io::MethodSection& section = *the_case.methods[m].section;
  for (const io::AnalysisSpec& spec : the_case.analyses) {
    if (spec.method != name_)
      continue;
    analyses_.push_back(create_analysis(spec, the_case, section, method.bodies.get()));
    prefixes_.push_back(spec.name.empty() ? "" : spec.name + ".");
    specs_.push_back(&spec);
    claim(spec.key, *analyses_.back(), prefixes_.back());
    const auto caveat = method.load_caveats.find(spec.body);
    const bool of_loads = spec.type == "body_loads" || spec.type == "power_number";
    load_caveats_.push_back(of_loads && caveat != method.load_caveats.end() ? caveat->second : "");
  }
  for (std::size_t k = 0; k < analyses_.size(); ++k) {
    if (own_schedule(k))
      own_.push_back(k);
    else
      column_count_ += analyses_[k]->columns().size();
    needs_body_forces_ = needs_body_forces_ || analyses_[k]->needs_body_forces();
  }
}

bool MethodOutputs::own_schedule(std::size_t k) const {
  return specs_[k] != nullptr && specs_[k]->sample_interval.has_value();
}

std::vector<analysis::Column> MethodOutputs::columns(bool prefixed) const {
  std::vector<analysis::Column> columns;
  for (std::size_t k = 0; k < analyses_.size(); ++k) {
    if (!own_schedule(k)) {
      for (analysis::Column& column : columns_of(k, prefixed))
        columns.push_back(std::move(column));
    }
  }
  return columns;
}

std::vector<analysis::Column> MethodOutputs::columns_of(std::size_t k, bool prefixed) const {
  std::vector<analysis::Column> columns = analyses_[k]->columns();
  for (analysis::Column& column : columns)
    column.name = (prefixed ? name_ + "." : "") + prefixes_[k] + column.name;
  return columns;
}

void MethodOutputs::sample(double time, std::span<double> values) {
  if (needs_body_forces_)
    method_.solver->update_body_forces();
  std::size_t first = 0;
  for (std::size_t k = 0; k < analyses_.size(); ++k) {
    if (own_schedule(k))
      continue;
    const std::size_t count = analyses_[k]->columns().size();
    analyses_[k]->sample(*method_.store, time, values.subspan(first, count));
    first += count;
  }
}

void MethodOutputs::replay(double time, std::span<const double> values) {
  std::size_t first = 0;
  for (std::size_t k = 0; k < analyses_.size(); ++k) {
    if (own_schedule(k))
      continue;
    const std::size_t count = analyses_[k]->columns().size();
    analyses_[k]->replay(time, values.subspan(first, count));
    first += count;
  }
}

void MethodOutputs::sample_one(std::size_t k, double time, std::span<double> values) {
  if (analyses_[k]->needs_body_forces())
    method_.solver->update_body_forces();
  analyses_[k]->sample(*method_.store, time, values);
}

void MethodOutputs::replay_one(std::size_t k, double time, std::span<const double> values) {
  analyses_[k]->replay(time, values);
}

void MethodOutputs::add_figures(analysis::Figures& figures, bool prefixed) const {
  for (std::size_t k = 0; k < analyses_.size(); ++k) {
    analysis::Figures own;
    analyses_[k]->add_figures(own);
    for (const auto& [figure, value] : own.values())
      figures.add((prefixed ? name_ + "." : "") + prefixes_[k] + figure, value, own.unit(figure));
  }
}

// The analyses' own caveats, then that of the body whose loads they measure, for all figures.
void MethodOutputs::add_caveats(analysis::Caveats& caveats, bool prefixed) const {
  for (std::size_t k = 0; k < analyses_.size(); ++k) {
    analysis::Caveats own;
    analyses_[k]->add_caveats(own);
    if (!load_caveats_[k].empty()) {
      analysis::Figures figures;
      analyses_[k]->add_figures(figures);
      for (const auto& entry : figures.values()) {
        std::string& reason = own[entry.first];
        reason = reason.empty() ? load_caveats_[k] : load_caveats_[k] + "; " + reason;
      }
    }
    for (const auto& [figure, reason] : own)
      caveats[(prefixed ? name_ + "." : "") + prefixes_[k] + figure] = reason;
  }
}

void MethodOutputs::open_frames(const std::filesystem::path& output_dir,
                                std::vector<io::PvdEntry> entries) {
  collection_ = std::make_unique<io::PvdWriter>(output_dir / collection_name(), std::move(entries));
}

std::string MethodOutputs::write_frame(const std::filesystem::path& output_dir, double time) {
  const std::string file =
      fmt::format("frames/{}_{:06d}.{}", name_, collection_->entries().size(), frame_extension());
  if (const GridFrame* grid = method_.solver->grid_frame())
    io::write_vti_frame(output_dir / file, *grid, time);
  else
    io::write_vtp_frame(output_dir / file, *method_.store, time, method_.solver->frame_arrays());
  collection_->add(time, file);
  return file;
}

}  // namespace partimix::app
