#include "app/runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "app/interrupt.hpp"
#include "app/output_folder.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "io/checkpoint_folder.hpp"
#include "io/run_metadata.hpp"
#include "particles/health.hpp"

namespace partimix::app {
namespace {

constexpr const char* kCheckpoints = "checkpoints";

std::string method_prefix(const std::string& name) {
  return "methods/" + name + "/";
}

std::string joined(const std::vector<io::SeriesColumn>& columns) {
  std::string text;
  for (const auto& column : columns)
    text += column.name + " [" + column.unit + "]\n";
  return text;
}

// The frames of a collection as two arrays: times, and paths one per line.
void save_frames(const MethodOutputs& outputs, StateArchive& archive) {
  std::vector<double> times;
  std::string paths;
  for (const io::PvdEntry& entry : outputs.frames()) {
    times.push_back(entry.time);
    paths += entry.path + "\n";
  }
  archive.put_doubles("frames/" + outputs.name() + "/times", times);
  archive.put_text("frames/" + outputs.name() + "/paths", paths);
}

std::vector<io::PvdEntry> restore_frames(const std::string& method, const StateArchive& archive) {
  const auto times = archive.doubles("frames/" + method + "/times");
  const std::string& paths = archive.text("frames/" + method + "/paths");
  std::vector<io::PvdEntry> entries;
  std::size_t begin = 0;
  for (const double time : times) {
    const std::size_t end = paths.find('\n', begin);
    if (end == std::string::npos)
      throw StateError("frames/" + method + "/paths: fewer paths than times");
    entries.push_back({time, paths.substr(begin, end - begin)});
    begin = end + 1;
  }
  return entries;
}

// Frame files of `method` numbered from `first` on: a resumed run writes them again, and must
// not leave those of the interrupted run beyond where it stops.
void remove_frames_from(const std::filesystem::path& frames, const std::string& method,
                        std::string_view extension, std::size_t first) {
  std::error_code error;
  for (std::size_t k = first;; ++k) {
    const auto file = frames / fmt::format("{}_{:06d}.{}", method, k, extension);
    if (!std::filesystem::remove(file, error))
      break;
  }
}

}  // namespace

Runner::Runner(const io::Case& the_case, Simulation& simulation, RunOptions options)
    : case_(the_case),
      simulation_(simulation),
      options_(std::move(options)),
      clock_(the_case, simulation) {
  for (std::size_t m = 0; m < simulation.methods.size(); ++m)
    outputs_.emplace_back(the_case, m, simulation.methods[m]);
  for (MethodOutputs& outputs : outputs_) {
    for (const std::size_t k : outputs.own_schedules())
      own_series_.emplace_back(outputs, k, !the_case.single_method());
  }
}

std::vector<io::SeriesColumn> Runner::series_columns() const {
  std::vector<io::SeriesColumn> columns{{"time", "s"}, {"step", ""}, {"dt", "s"}};
  for (const MethodOutputs& outputs : outputs_) {
    for (const auto& column : outputs.columns(!case_.single_method()))
      columns.push_back(column);
  }
  return columns;
}

// Clears what an earlier run wrote in the folder (app/output_folder.hpp), so that no stale
// frame or checkpoint mixes in, and lists what this run writes.
void Runner::start_fresh() {
  namespace fs = std::filesystem;
  const fs::path& out = options_.output_dir;
  prepare_output_folder(out, options_.overwrite);
  std::vector<std::string> products{"series.csv", "run.json", "frames", kCheckpoints};
  for (const MethodOutputs& outputs : outputs_)
    products.push_back(outputs.collection_name());
  for (const std::string& product : products)
    record_output(out, product);
  std::error_code error;
  fs::create_directories(out / "frames", error);
  if (error) {
    throw RunError(
        fmt::format("cannot prepare the output folder {}: {}", out.string(), error.message()));
  }
  series_ = std::make_unique<io::SeriesWriter>(out / "series.csv", series_columns());
  for (AnalysisSeries& series : own_series_) {
    record_output(out, series.file_name());
    series.start_fresh(out);
  }
  for (MethodOutputs& outputs : outputs_)
    outputs.open_frames(out, {});
  state_ = RunState{};
  state_.next_sample = case_.time.sample_interval;
  state_.next_frame = case_.time.output_interval;
  state_.next_checkpoint = case_.time.checkpoint_interval;
}

// The methods, couplings and clock from the checkpoint; then series.csv and the collections
// rewritten to what they were when it was written, and the analyses given their history back.
void Runner::start_from(const StateArchive& checkpoint) {
  const std::filesystem::path& out = options_.output_dir;
  for (std::size_t m = 0; m < simulation_.methods.size(); ++m)
    simulation_.methods[m].solver->restore(checkpoint, method_prefix(case_.methods[m].name));
  for (std::size_t c = 0; c < simulation_.couplings.size(); ++c)
    simulation_.couplings[c]->restore(checkpoint, fmt::format("couplings/{}/", c));
  state_ = restore_run_state(checkpoint);
  const std::vector<io::SeriesColumn> columns = series_columns();
  if (checkpoint.text("series/columns") != joined(columns))
    throw StateError("series/columns: the checkpoint's analyses differ from the case's");
  const auto rows = checkpoint.doubles("series/rows", columns.size());
  rows_.assign(rows.begin(), rows.end());
  for (std::size_t first = 0; first < rows_.size(); first += columns.size()) {
    const std::span<const double> row(&rows_[first], columns.size());
    std::size_t offset = 3;
    for (MethodOutputs& outputs : outputs_) {
      outputs.replay(row[0], row.subspan(offset, outputs.column_count()));
      offset += outputs.column_count();
    }
  }
  for (AnalysisSeries& series : own_series_)
    series.restore(checkpoint);
  std::vector<std::vector<io::PvdEntry>> frames;
  for (const MethodOutputs& outputs : outputs_)
    frames.push_back(restore_frames(outputs.name(), checkpoint));
  // All read: now the files go back to where the checkpoint left them.
  std::filesystem::create_directories(out / "frames");
  series_ = std::make_unique<io::SeriesWriter>(out / "series.csv", columns, rows_);
  for (AnalysisSeries& series : own_series_)
    series.reopen(out);
  for (std::size_t m = 0; m < outputs_.size(); ++m) {
    remove_frames_from(out / "frames", outputs_[m].name(), outputs_[m].frame_extension(),
                       frames[m].size());
    outputs_[m].open_frames(out, std::move(frames[m]));
  }
}

void Runner::sample(double time, std::uint64_t steps, double dt) {
  row_.assign({time, static_cast<double>(steps), dt});
  for (MethodOutputs& outputs : outputs_) {
    const std::size_t first = row_.size();
    row_.resize(first + outputs.column_count());
    outputs.sample(time, std::span<double>(row_).subspan(first));
  }
  series_->write_row(row_);
  rows_.insert(rows_.end(), row_.begin(), row_.end());
  state_.last_sample_time = time;
}

void Runner::write_frames(double time) {
  for (MethodOutputs& outputs : outputs_)
    record_output(options_.output_dir, outputs.write_frame(options_.output_dir, time));
  state_.last_frame_time = time;
}

// Everything the run needs to go on (docs/architecture-notes.md, "Checkpoints"), in
// checkpoints/checkpoint_<step>.h5; the last two are kept.
void Runner::write_checkpoint() {
  const double before = state_.wall_seconds;
  state_.wall_seconds = wall_seconds();
  StateArchive archive;
  archive.put_text("case/file", case_.file);
  archive.put_text("case/resolved", case_.resolved.dump());
  save_run_state(state_, archive);
  const std::vector<io::SeriesColumn> columns = series_columns();
  archive.put_text("series/columns", joined(columns));
  archive.put_doubles("series/rows", rows_, columns.size());
  for (const AnalysisSeries& series : own_series_)
    series.save(archive);
  for (std::size_t m = 0; m < simulation_.methods.size(); ++m) {
    simulation_.methods[m].solver->save(archive, method_prefix(case_.methods[m].name));
    save_frames(outputs_[m], archive);
  }
  for (std::size_t c = 0; c < simulation_.couplings.size(); ++c)
    simulation_.couplings[c]->save(archive, fmt::format("couplings/{}/", c));
  state_.wall_seconds = before;
  const io::CheckpointFolder folder(options_.output_dir / kCheckpoints);
  last_checkpoint_ = folder.write(state_.steps, archive);
  record_output(options_.output_dir,
                last_checkpoint_.lexically_relative(options_.output_dir).string());
}

void Runner::write_metadata(const io::RunSummary& summary) const {
  const bool prefixed = !case_.single_method();
  nlohmann::json parameters = nlohmann::json::object();
  nlohmann::json methods = nlohmann::json::array();
  for (std::size_t m = 0; m < simulation_.methods.size(); ++m) {
    const io::MethodInstance& method = simulation_.methods[m];
    const std::string& name = case_.methods[m].name;
    for (const auto& [parameter, value] : method.solver->derived_parameters())
      parameters[prefixed ? name + "." + parameter : parameter] = value;
    methods.push_back({{"name", name},
                       {"sub_steps", case_.methods[m].sub_steps},
                       {"particles", method.store->size()}});
  }
  for (std::size_t k = 0; k < simulation_.couplings.size(); ++k)
    for (const auto& [parameter, value] : simulation_.couplings[k]->derived_parameters())
      parameters[fmt::format("couplings[{}].{}", k, parameter)] = value;
  nlohmann::json figures = nlohmann::json::object();
  nlohmann::json units = nlohmann::json::object();
  for (const auto& [name, value] : figures_.values()) {
    figures[name] = value;
    units[name] = figures_.unit(name).empty() ? "-" : figures_.unit(name);
  }
  nlohmann::json caveats = nlohmann::json::object();
  for (const auto& [name, reason] : caveats_)
    caveats[name] = reason;
  nlohmann::json content{{"partimix_version", PARTIMIX_VERSION},
                         {"case_file", case_.file},
                         {"case", case_.resolved},
                         {"methods", methods},
                         {"derived", parameters},
                         {"warnings", simulation_.warnings},
                         {"run", io::to_json(summary)},
                         {"figures", figures},
                         {"figure_units", units},
                         {"caveats", caveats}};
  if (!last_checkpoint_.empty())
    content["checkpoint"] = last_checkpoint_.lexically_relative(options_.output_dir).string();
  io::write_run_json(options_.output_dir / "run.json", content);
}

// One step of the clock; false (and the summary says why) when the run cannot go on.
bool Runner::step_once(io::RunSummary& summary) {
  const double tolerance = 1e-9 * case_.time.end;
  std::string why;
  const std::optional<double> dt = clock_.next_step(case_.time.end - state_.time, why);
  if (dt && !(*dt > tolerance))
    why = fmt::format("the time step fell to {:.3g} s", *dt);
  if (!why.empty()) {
    summary.status = "failed";
    summary.message = fmt::format("step {}, t = {:.6g} s: {}", state_.steps, state_.time, why);
    return false;
  }
  clock_.advance(state_.time, *dt);
  state_.time += *dt;
  ++state_.steps;
  state_.last_dt = *dt;
  for (const io::MethodInstance& method : simulation_.methods) {
    if (const auto bad = find_bad_particle(*method.store, method.solver->domain())) {
      summary.status = "failed";
      summary.message = fmt::format("step {}, t = {:.6g} s: {}", state_.steps, state_.time, *bad);
      return false;
    }
  }
  return true;
}

io::RunSummary Runner::run(const StateArchive* checkpoint) {
  if (checkpoint != nullptr)
    start_from(*checkpoint);
  else
    start_fresh();
  io::RunSummary summary{"running",       "", simulation_.particle_count(), 0, 0.0, 0.0,
                         options_.threads};
  first_step_ = state_.steps;
  wall_.restart();
  write_progress(summary);
  std::optional<Progress> progress;
  if (options_.show_progress)
    progress.emplace(case_.time.end, stderr, isatty(fileno(stderr)) != 0);
  try {
    if (checkpoint == nullptr) {
      sample(0.0, 0, 0.0);
      for (AnalysisSeries& series : own_series_)
        series.sample_if_due(0.0, 0, 0.0, 1e-9 * case_.time.end);
      if (case_.output.frames)
        write_frames(0.0);
    }
    summary.status = "completed";
    loop(summary, progress);
  } catch (const RunError& error) {
    summary.status = "failed";
    summary.message =
        fmt::format("step {}, t = {:.6g} s: {}", state_.steps, state_.time, error.what());
  }
  if (progress)
    progress->finish();
  finish(summary);
  return summary;
}

// Steps until the end time, an interrupt or a failure (summary says which), sampling, writing
// frames and checkpoints on the way; run.json follows every frame and checkpoint.
void Runner::loop(io::RunSummary& summary, std::optional<Progress>& progress) {
  const io::TimeControl& time = case_.time;
  const double tolerance = 1e-9 * time.end;
  while (state_.time < time.end - tolerance) {
    if (interrupt_requested()) {
      summary.status = "interrupted";
      summary.message =
          fmt::format("interrupted at step {}, t = {:.6g} s", state_.steps, state_.time);
      write_checkpoint();
      return;
    }
    if (!step_once(summary))
      return;
    const double t = state_.time;
    const bool frame_due = case_.output.frames && t >= state_.next_frame - tolerance;
    const bool checkpoint_due =
        time.checkpoint_interval > 0.0 && t >= state_.next_checkpoint - tolerance;
    // run.json first: whatever a kill interrupts next, it already tells how far the run came.
    if (frame_due || checkpoint_due)
      write_progress(summary);
    if (t >= state_.next_sample - tolerance) {
      sample(t, state_.steps, state_.last_dt);
      state_.next_sample = next_multiple(time.sample_interval, t, tolerance);
    }
    for (AnalysisSeries& series : own_series_)
      series.sample_if_due(t, state_.steps, state_.last_dt, tolerance);
    if (frame_due) {
      write_frames(t);
      state_.next_frame = next_multiple(time.output_interval, t, tolerance);
    }
    if (checkpoint_due) {
      state_.next_checkpoint = next_multiple(time.checkpoint_interval, t, tolerance);
      write_checkpoint();
    }
    if (progress)
      progress->update(t, state_.steps, summary.particles);
  }
}

// run.json of a run under way: status "running", the steps and time so far.
void Runner::write_progress(const io::RunSummary& summary) {
  io::RunSummary now = summary;
  now.status = "running";
  now.steps = state_.steps;
  now.simulated_time = state_.time;
  now.wall_seconds = wall_seconds();
  count_this_process(now);
  write_metadata(now);
}

// The wall time of the run so far, this process and those before it (a resumed run).
double Runner::wall_seconds() const {
  return state_.wall_seconds + wall_.seconds();
}

void Runner::count_this_process(io::RunSummary& summary) const {
  summary.process_steps = state_.steps - first_step_;
  summary.process_wall_seconds = wall_.seconds();
}

// The last sample and frame at the time the run stopped (unless it failed), the figures and
// run.json.
void Runner::finish(io::RunSummary& summary) {
  if (summary.status != "failed") {
    if (state_.last_sample_time != state_.time)
      sample(state_.time, state_.steps, state_.last_dt);
    for (AnalysisSeries& series : own_series_)
      series.finish(state_.time, state_.steps, state_.last_dt);
    if (case_.output.frames && state_.last_frame_time != state_.time)
      write_frames(state_.time);
  }
  summary.steps = state_.steps;
  summary.simulated_time = state_.time;
  summary.wall_seconds = wall_seconds();
  count_this_process(summary);
  for (const MethodOutputs& outputs : outputs_)
    outputs.add_figures(figures_, !case_.single_method());
  for (const MethodOutputs& outputs : outputs_)
    outputs.add_caveats(caveats_, !case_.single_method());
  write_metadata(summary);
}

}  // namespace partimix::app
