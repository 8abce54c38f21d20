#include "app/runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <fmt/format.h>

#include "analysis/kinetic_energy.hpp"
#include "analysis/max_speed.hpp"
#include "app/interrupt.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "io/run_metadata.hpp"
#include "io/vtk_frame_writer.hpp"
#include "particles/health.hpp"

namespace partimix::app {
namespace {

// K_s and n of Reynolds numbers (docs/power.md); the loader admits power numbers only for
// these models.
analysis::FlowScales flow_scales(const io::FluidSpec& fluid) {
  const sph::RheologyConfig& rheology = fluid.rheology;
  if (rheology.model == "newtonian")
    return {fluid.density, rheology.viscosity, 1.0};
  return {fluid.density, rheology.consistency, rheology.flow_index};
}

analysis::AnalysisOptions options_of(const io::AnalysisSpec& spec, const io::Case& the_case,
                                     const geometry::MovingBodies* bodies) {
  analysis::AnalysisOptions options;
  options.axis = spec.axis;
  options.diameter = spec.diameter;
  options.metzner_otto = spec.metzner_otto;
  options.fluid = flow_scales(the_case.fluid);
  options.mixing = spec.mixing;
  options.packing = spec.packing;
  options.profile = spec.profile;
  options.repose = spec.repose;
  if (spec.type == "body_loads" || spec.type == "power_number") {
    if (bodies == nullptr)
      throw RunError("the analysis '" + spec.type + "' needs the bodies of the simulation");
    const auto body = static_cast<std::size_t>(spec.body);
    options.body = {spec.body, &bodies->motion(body), the_case.walls[body].motion,
                    spec.vessel_axis_point, spec.average_revolutions};
  }
  return options;
}

// Kinetic energy reads the particle fields at set-up: its rotational column exists only for
// particles with angular velocities and radii (DEM).
std::vector<std::unique_ptr<analysis::Analysis>> make_analyses(const io::Case& the_case,
                                                               const geometry::MovingBodies* bodies,
                                                               const ParticleStore& particles) {
  std::vector<std::unique_ptr<analysis::Analysis>> analyses;
  analyses.push_back(std::make_unique<analysis::KineticEnergy>(particles));
  analyses.push_back(std::make_unique<analysis::MaxSpeed>());
  for (const auto& spec : the_case.analyses) {
    analyses.push_back(
        analysis::analysis_registry().create(spec.type, options_of(spec, the_case, bodies)));
  }
  return analyses;
}

std::vector<io::SeriesColumn> series_columns(
    const std::vector<std::unique_ptr<analysis::Analysis>>& analyses) {
  std::vector<io::SeriesColumn> columns{{"time", "s"}, {"step", ""}, {"dt", "s"}};
  for (const auto& a : analyses) {
    for (const auto& column : a->columns())
      columns.push_back(column);
  }
  return columns;
}

}  // namespace

Runner::Runner(const io::Case& the_case, Solver& solver, const geometry::MovingBodies* bodies,
               RunOptions options)
    : case_(the_case),
      solver_(solver),
      options_(std::move(options)),
      analyses_(make_analyses(the_case, bodies, solver.particles())) {
  for (const auto& a : analyses_)
    needs_body_forces_ = needs_body_forces_ || a->needs_body_forces();
}

// Removes what an earlier run left in the folder, so that no stale frame mixes in.
void Runner::prepare_output_dir() const {
  namespace fs = std::filesystem;
  const fs::path& out = options_.output_dir;
  std::error_code error;
  for (const char* product : {"frames", "plots", "series.csv", "run.json", "particles.pvd"}) {
    fs::remove_all(out / product, error);
    if (error)
      break;
  }
  if (!error)
    fs::create_directories(out / "frames", error);
  if (error) {
    throw RunError(
        fmt::format("cannot prepare the output folder {}: {}", out.string(), error.message()));
  }
}

void Runner::sample(double time, std::size_t steps, double dt) {
  row_.clear();
  row_.push_back(time);
  row_.push_back(static_cast<double>(steps));
  row_.push_back(dt);
  if (needs_body_forces_)
    solver_.update_body_forces();
  for (const auto& a : analyses_) {
    const std::size_t first = row_.size();
    row_.resize(first + a->columns().size());
    a->sample(solver_.particles(), time, std::span<double>(row_).subspan(first));
  }
  series_->write_row(row_);
  last_sample_time_ = time;
}

void Runner::write_frame(double time) {
  const std::string name = fmt::format("frames/particles_{:06d}.vtp", frames_written_);
  io::write_vtp_frame(options_.output_dir / name, solver_.particles(), time);
  collection_->add(time, name);
  ++frames_written_;
  last_frame_time_ = time;
}

void Runner::write_metadata(const io::RunSummary& summary) const {
  nlohmann::json parameters;
  for (const auto& [name, value] : solver_.derived_parameters())
    parameters[name] = value;
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [name, value] : figures_)
    figures[name] = value;
  const nlohmann::json content{{"partimix_version", PARTIMIX_VERSION},
                               {"case_file", case_.file},
                               {"case", case_.resolved},
                               {"derived", parameters},
                               {"run", io::to_json(summary)},
                               {"figures", figures}};
  io::write_run_json(options_.output_dir / "run.json", content);
}

io::RunSummary Runner::run() {
  prepare_output_dir();
  series_ = std::make_unique<io::SeriesWriter>(options_.output_dir / "series.csv",
                                               series_columns(analyses_));
  collection_ = std::make_unique<io::PvdWriter>(options_.output_dir / "particles.pvd");
  const io::TimeControl& time = case_.time;
  const std::size_t particles = solver_.particles().size();
  io::RunSummary summary{"running", "", particles, 0, 0.0, 0.0, options_.threads};
  write_metadata(summary);
  std::optional<Progress> progress;
  if (options_.show_progress)
    progress.emplace(time.end, stderr, isatty(fileno(stderr)) != 0);
  Stopwatch wall;
  const double tolerance = 1e-9 * time.end;
  double t = 0.0;
  std::size_t steps = 0;
  double last_dt = 0.0;
  sample(t, steps, 0.0);
  if (case_.output.frames)
    write_frame(t);
  double next_sample = time.sample_interval;
  double next_frame = time.output_interval;
  summary.status = "completed";
  while (t < time.end - tolerance) {
    if (interrupt_requested()) {
      summary.status = "interrupted";
      summary.message = fmt::format("interrupted at step {}, t = {:.6g} s", steps, t);
      break;
    }
    const double dt = std::min(solver_.stable_dt(), time.end - t);
    last_dt = dt;
    if (!(dt > tolerance)) {
      summary.status = "failed";
      summary.message =
          fmt::format("step {}, t = {:.6g} s: the time step fell to {:.3g} s", steps, t, dt);
      break;
    }
    solver_.step(dt);
    t += dt;
    ++steps;
    if (const auto bad = find_bad_particle(solver_.particles(), solver_.domain())) {
      summary.status = "failed";
      summary.message = fmt::format("step {}, t = {:.6g} s: {}", steps, t, *bad);
      break;
    }
    if (t >= next_sample - tolerance) {
      sample(t, steps, dt);
      while (next_sample <= t + tolerance)
        next_sample += time.sample_interval;
    }
    if (case_.output.frames && t >= next_frame - tolerance) {
      write_frame(t);
      while (next_frame <= t + tolerance)
        next_frame += time.output_interval;
    }
    if (progress)
      progress->update(t, steps, particles);
  }
  if (summary.status != "failed") {
    if (last_sample_time_ != t)
      sample(t, steps, last_dt);
    if (case_.output.frames && last_frame_time_ != t)
      write_frame(t);
  }
  if (progress)
    progress->finish();
  summary.steps = steps;
  summary.simulated_time = t;
  summary.wall_seconds = wall.seconds();
  for (const auto& a : analyses_)
    a->add_figures(figures_);
  write_metadata(summary);
  return summary;
}

}  // namespace partimix::app
