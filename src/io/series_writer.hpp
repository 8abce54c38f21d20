#pragma once
// series.csv: one row per sample time, one named column per quantity, with the unit in the
// header ("time [s],kinetic_energy [J]"). Each row goes to the file in one write() as it is
// written, so a run that dies, even by SIGKILL, keeps every row it sampled and never a half one.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"

namespace partimix::io {

// A column's name and unit; an empty unit is written as [-].
using SeriesColumn = analysis::Column;

class SeriesWriter {
 public:
  // Writes the header and then `rows` (row-major, one value per column: the rows of a resumed
  // run before its checkpoint) to the file, replacing it atomically, and opens it to append.
  // Throws std::invalid_argument if a column name is empty, repeated, or holds a comma, quote or
  // line break (or a unit does), or the rows do not fill whole rows, and RunError naming the
  // file if it cannot be written.
  SeriesWriter(const std::filesystem::path& file, std::vector<SeriesColumn> columns,
               std::span<const double> rows = {});
  ~SeriesWriter();
  SeriesWriter(const SeriesWriter&) = delete;
  SeriesWriter& operator=(const SeriesWriter&) = delete;

  // Appends one row, one value per column in column order, with 10 significant digits.
  // Throws std::invalid_argument if the count differs from the columns, RunError on I/O failure.
  void write_row(std::span<const double> values);

  const std::vector<SeriesColumn>& columns() const { return columns_; }

 private:
  std::string format_row(std::span<const double> values) const;

  std::filesystem::path file_;
  std::vector<SeriesColumn> columns_;
  int descriptor_ = -1;
};

}  // namespace partimix::io
