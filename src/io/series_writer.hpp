#pragma once
// series.csv: one row per sample time, one named column per quantity, with the unit in the
// header ("time [s],kinetic_energy [J]"). Each row is flushed as it is written, so a run that
// dies keeps every row it sampled.
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"

namespace partimix::io {

// A column's name and unit; an empty unit is written as [-].
using SeriesColumn = analysis::Column;

class SeriesWriter {
 public:
  // Creates (or truncates) the file and writes the header. Throws std::invalid_argument if a
  // column name is empty, repeated, or holds a comma, quote or line break (or a unit does),
  // and RunError naming the file if it cannot be written.
  SeriesWriter(const std::filesystem::path& file, std::vector<SeriesColumn> columns);

  // Appends one row, one value per column in column order, with 10 significant digits.
  // Throws std::invalid_argument if the count differs from the columns, RunError on I/O failure.
  void write_row(std::span<const double> values);

  const std::vector<SeriesColumn>& columns() const { return columns_; }

 private:
  void flush_line(const std::string& line);

  std::filesystem::path file_;
  std::vector<SeriesColumn> columns_;
  std::ofstream out_;
};

}  // namespace partimix::io
