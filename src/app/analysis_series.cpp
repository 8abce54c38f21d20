#include "app/analysis_series.hpp"

#include <span>

#include "app/run_state.hpp"
#include "core/error.hpp"

namespace partimix::app {

AnalysisSeries::AnalysisSeries(MethodOutputs& outputs, std::size_t k, bool prefixed)
    : outputs_(outputs), k_(k), prefixed_(prefixed), next_(spec().sample_from) {}

std::vector<io::SeriesColumn> AnalysisSeries::columns() const {
  std::vector<io::SeriesColumn> columns{{"time", "s"}, {"step", ""}, {"dt", "s"}};
  for (analysis::Column& column : outputs_.columns_of(k_, prefixed_))
    columns.push_back(std::move(column));
  return columns;
}

void AnalysisSeries::start_fresh(const std::filesystem::path& output_dir) {
  writer_ = std::make_unique<io::SeriesWriter>(output_dir / file_name(), columns());
}

void AnalysisSeries::restore(const StateArchive& checkpoint) {
  const std::size_t width = columns().size();
  const auto rows = checkpoint.doubles(key("rows"), width);
  next_ = checkpoint.scalar(key("next"));
  last_ = checkpoint.scalar(key("last"));
  rows_.assign(rows.begin(), rows.end());
  for (std::size_t first = 0; first < rows_.size(); first += width) {
    const std::span<const double> row(&rows_[first], width);
    outputs_.replay_one(k_, row[0], row.subspan(3));
  }
}

void AnalysisSeries::reopen(const std::filesystem::path& output_dir) {
  writer_ = std::make_unique<io::SeriesWriter>(output_dir / file_name(), columns(), rows_);
}

void AnalysisSeries::save(StateArchive& archive) const {
  archive.put_doubles(key("rows"), rows_, columns().size());
  archive.put_scalar(key("next"), next_);
  archive.put_scalar(key("last"), last_);
}

void AnalysisSeries::sample_if_due(double time, std::uint64_t steps, double dt, double tolerance) {
  if (time < next_ - tolerance || next_ > spec().sample_until + tolerance)
    return;
  sample(time, steps, dt);
  next_ = spec().sample_from +
          next_multiple(*spec().sample_interval, time - spec().sample_from, tolerance);
}

void AnalysisSeries::finish(double time, std::uint64_t steps, double dt) {
  if (last_ != time && time >= spec().sample_from && time <= spec().sample_until)
    sample(time, steps, dt);
}

void AnalysisSeries::sample(double time, std::uint64_t steps, double dt) {
  row_.assign({time, static_cast<double>(steps), dt});
  row_.resize(writer_->columns().size());
  outputs_.sample_one(k_, time, std::span<double>(row_).subspan(3));
  writer_->write_row(row_);
  rows_.insert(rows_.end(), row_.begin(), row_.end());
  last_ = time;
}

}  // namespace partimix::app
