#pragma once
// The run loop (DESIGN.md, "One run"): step the methods on one clock (app/run_clock.hpp),
// sample their analyses into series.csv, write each method's VTK frames and .pvd collection,
// write checkpoints, report progress, and stop cleanly on Ctrl-C (after a frame and a
// checkpoint) or with a reason on a blow-up (keeping the last good frame). A run can start from
// a checkpoint and then goes on exactly as the run that wrote it would have.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/analysis_series.hpp"
#include "app/method_outputs.hpp"
#include "app/run_clock.hpp"
#include "app/run_state.hpp"
#include "app/simulation.hpp"
#include "core/progress.hpp"
#include "core/state_archive.hpp"
#include "core/stopwatch.hpp"
#include "io/case.hpp"
#include "io/run_metadata.hpp"
#include "io/series_writer.hpp"

namespace partimix::app {

struct RunOptions {
  std::filesystem::path output_dir;
  int threads = 1;
  bool show_progress = true;
  bool overwrite = false;  // write into a folder with files partimix did not write
};

class Runner {
 public:
  // `simulation` is built from `the_case` (build_simulation) and outlives the runner.
  Runner(const io::Case& the_case, Simulation& simulation, RunOptions options);

  // Runs to the case's end time; returns the summary also written to run.json (status:
  // completed, interrupted or failed). With a checkpoint (of this case, app/checkpoint_match),
  // the methods, the analyses, series.csv and the frame collections are first put back where
  // the checkpoint left them (the simulation must then be built with for_restore); throws
  // StateError when the checkpoint does not fit the simulation.
  io::RunSummary run(const StateArchive* checkpoint = nullptr);

  // The analyses' summary figures (time averages, final values) of the last run, also in
  // run.json under "figures".
  const std::map<std::string, double>& figures() const { return figures_.values(); }
  const std::map<std::string, std::string>& figure_units() const { return figures_.units(); }
  // Why some figures are unreliable (MethodOutputs::add_caveats), also in run.json "caveats".
  const analysis::Caveats& caveats() const { return caveats_; }

 private:
  void start_fresh();
  void start_from(const StateArchive& checkpoint);
  void sample(double time, std::uint64_t steps, double dt);
  void write_frames(double time);
  void write_checkpoint();
  void write_metadata(const io::RunSummary& summary) const;
  std::vector<io::SeriesColumn> series_columns() const;
  bool step_once(io::RunSummary& summary);
  void loop(io::RunSummary& summary, std::optional<Progress>& progress);
  void write_progress(const io::RunSummary& summary);
  double wall_seconds() const;
  // The steps and wall time of this process alone into the summary.
  void count_this_process(io::RunSummary& summary) const;
  void finish(io::RunSummary& summary);

  const io::Case& case_;
  Simulation& simulation_;
  RunOptions options_;
  RunClock clock_;
  std::vector<MethodOutputs> outputs_;      // one per method
  std::vector<AnalysisSeries> own_series_;  // the analyses on a schedule of their own
  std::unique_ptr<io::SeriesWriter> series_;
  std::vector<double> rows_;  // every row sampled, full precision, for checkpoints
  std::vector<double> row_;
  RunState state_;
  analysis::Figures figures_;
  analysis::Caveats caveats_;
  std::filesystem::path last_checkpoint_;
  Stopwatch wall_;                // since this process started the run
  std::uint64_t first_step_ = 0;  // the run's step count when this process took it up
};

}  // namespace partimix::app
