#pragma once
// What a run writes of one method (DESIGN.md, "Inputs, outputs, errors"): its analyses, which
// fill its part of each series.csv row, and its frame series, frames/<method>_NNNNNN.vtp listed
// in <method>.pvd (.vti, the cells, for a method on a grid). With several methods every series
// column is named <method>.<column>.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"
#include "io/case.hpp"
#include "io/method_type.hpp"
#include "io/pvd_writer.hpp"

namespace partimix::app {

class MethodOutputs {
 public:
  // The analyses of method `m` of the case (kinetic energy and the largest speed, then the
  // case's analyses of this method, in case order). Throws InputError at the analysis' key
  // when it needs what the method does not have (bodies) or when two analyses would write the
  // same column (two power numbers without distinct `name`s).
  MethodOutputs(const io::Case& the_case, std::size_t m, const io::MethodInstance& method);

  const std::string& name() const { return name_; }
  // The series.csv columns of the analyses (all but those on a schedule of their own), each
  // named "<analysis name>.<column>" when the analysis has a name, and prefixed with
  // "<method>." when `prefixed`.
  std::vector<analysis::Column> columns(bool prefixed) const;
  std::size_t column_count() const { return column_count_; }

  // Samples the series.csv analyses into `values` (column_count() of them).
  void sample(double time, std::span<double> values);
  // Gives them the values they sampled before a checkpoint (Analysis::replay).
  void replay(double time, std::span<const double> values);

  // The analyses on a schedule of their own (analyses[i].sample_interval), by index k, with
  // their spec, columns, sampling and replay one at a time (app/analysis_series.hpp).
  const std::vector<std::size_t>& own_schedules() const { return own_; }
  const io::AnalysisSpec& spec_of(std::size_t k) const { return *specs_[k]; }
  std::vector<analysis::Column> columns_of(std::size_t k, bool prefixed) const;
  void sample_one(std::size_t k, double time, std::span<double> values);
  void replay_one(std::size_t k, double time, std::span<const double> values);
  void add_figures(analysis::Figures& figures, bool prefixed) const;
  // Why some of those figures are unreliable (Analysis::add_caveats, and the load caveats of the
  // method's bodies for the analyses of their loads), under the same names.
  void add_caveats(analysis::Caveats& caveats, bool prefixed) const;

  // The frame series: starts the collection afresh, or with the frames before a checkpoint.
  void open_frames(const std::filesystem::path& output_dir, std::vector<io::PvdEntry> entries);
  // Writes the frame at `time` and returns its path relative to output_dir.
  std::string write_frame(const std::filesystem::path& output_dir, double time);
  const std::vector<io::PvdEntry>& frames() const { return collection_->entries(); }
  std::string collection_name() const { return name_ + ".pvd"; }
  // "vti" for a method on a grid (its cells, Solver::grid_frame), else "vtp" (its particles).
  const std::string& frame_extension() const { return frame_extension_; }

 private:
  std::string name_;
  const io::MethodInstance& method_;
  std::vector<std::unique_ptr<analysis::Analysis>> analyses_;
  std::vector<std::string> prefixes_;           // parallel to analyses_: "<name>." or empty
  std::vector<std::string> load_caveats_;       // parallel to analyses_: its body's, or empty
  std::vector<const io::AnalysisSpec*> specs_;  // parallel to analyses_: null for built-ins
  std::vector<std::size_t> own_;                // the analyses on their own schedule
  bool own_schedule(std::size_t k) const;
  std::size_t column_count_ = 0;
  bool needs_body_forces_ = false;
  std::unique_ptr<io::PvdWriter> collection_;
  std::string frame_extension_;
};

}  // namespace partimix::app
