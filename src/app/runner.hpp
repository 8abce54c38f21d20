#pragma once
// The run loop (DESIGN.md, "One run"): step the solver with its stable time step, sample the
// analyses into series.csv, write VTK frames and the .pvd collection, report progress, and
// stop cleanly on Ctrl-C or with a reason on a blow-up (keeping the last good frame).
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"
#include "geometry/moving_bodies.hpp"
#include "io/case.hpp"
#include "io/pvd_writer.hpp"
#include "io/run_metadata.hpp"
#include "io/series_writer.hpp"
#include "particles/solver.hpp"

namespace partimix::app {

struct RunOptions {
  std::filesystem::path output_dir;
  int threads = 1;
  bool show_progress = true;
};

class Runner {
 public:
  // `bodies` (may be null when the case has no load analyses) are the bodies of the solver.
  Runner(const io::Case& the_case, Solver& solver, const geometry::MovingBodies* bodies,
         RunOptions options);

  // Runs to the case's end time; returns the summary also written to run.json
  // (status: completed, interrupted or failed).
  io::RunSummary run();

  // The analyses' summary figures (time averages, final values) of the last run, also in
  // run.json under "figures".
  const std::map<std::string, double>& figures() const { return figures_; }

 private:
  void prepare_output_dir() const;
  void sample(double time, std::size_t steps, double dt);
  void write_frame(double time);
  void write_metadata(const io::RunSummary& summary) const;

  const io::Case& case_;
  Solver& solver_;
  RunOptions options_;
  std::vector<std::unique_ptr<analysis::Analysis>> analyses_;
  std::unique_ptr<io::SeriesWriter> series_;
  std::unique_ptr<io::PvdWriter> collection_;
  std::vector<double> row_;
  std::map<std::string, double> figures_;
  bool needs_body_forces_ = false;
  std::size_t frames_written_ = 0;
  double last_frame_time_ = -1.0;
  double last_sample_time_ = -1.0;
};

}  // namespace partimix::app
