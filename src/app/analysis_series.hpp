#pragma once
// An analysis on a schedule of its own (docs/case-reference.md, "analyses": sample_interval,
// sample_from, sample_until): its rows, time, step, dt and its columns, go to
// series_<name>.csv at the multiples of its interval within its span, so that a short event is
// sampled finely inside a long run without a huge series.csv. Checkpoints hold its rows and its
// next sample time, and a resumed run replays the rows to the analysis.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/method_outputs.hpp"
#include "core/state_archive.hpp"
#include "io/series_writer.hpp"

namespace partimix::app {

class AnalysisSeries {
 public:
  // Analysis `k` of `outputs` (one of its own_schedules()); columns prefixed with the method's
  // name when `prefixed`.
  AnalysisSeries(MethodOutputs& outputs, std::size_t k, bool prefixed);

  std::string file_name() const { return "series_" + spec().name + ".csv"; }

  // Starts the file afresh in `output_dir`.
  void start_fresh(const std::filesystem::path& output_dir);
  // Takes the rows and the next sample time of `checkpoint` (the rows replayed to the
  // analysis); throws StateError when they do not fit. Then reopen() rewrites the file with them.
  void restore(const StateArchive& checkpoint);
  void reopen(const std::filesystem::path& output_dir);
  void save(StateArchive& archive) const;

  // Samples at `time` if a sample time of the span (sample_from + j sample_interval, up to
  // sample_until) is due: at the first step at or past it, as series.csv.
  void sample_if_due(double time, std::uint64_t steps, double dt, double tolerance);
  // The last sample at the run's end time, when the span reaches it and it was not sampled.
  void finish(double time, std::uint64_t steps, double dt);

 private:
  const io::AnalysisSpec& spec() const { return outputs_.spec_of(k_); }
  std::vector<io::SeriesColumn> columns() const;
  std::string key(const std::string& what) const { return "series/" + file_name() + "/" + what; }
  void sample(double time, std::uint64_t steps, double dt);

  MethodOutputs& outputs_;
  std::size_t k_;
  bool prefixed_;
  std::unique_ptr<io::SeriesWriter> writer_;
  std::vector<double> rows_;  // every row, full precision, for checkpoints
  std::vector<double> row_;
  double next_ = 0.0;
  double last_ = -1.0;
};

}  // namespace partimix::app
