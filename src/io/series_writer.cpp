#include "io/series_writer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/error.hpp"

namespace partimix::io {
namespace {

bool fits_csv_header(std::string_view text) {
  return text.find_first_of(",\"\r\n") == std::string_view::npos;
}

void check_columns(const std::vector<SeriesColumn>& columns) {
  std::set<std::string> seen;
  for (const auto& column : columns) {
    if (column.name.empty() || !fits_csv_header(column.name) || !fits_csv_header(column.unit)) {
      throw std::invalid_argument("series column '" + column.name + "' [" + column.unit +
                                  "]: a name must be non-empty and neither name nor unit may "
                                  "hold a comma, quote or line break");
    }
    if (!seen.insert(column.name).second) {
      throw std::invalid_argument("series column '" + column.name + "' appears twice");
    }
  }
}

std::string header_line(const std::vector<SeriesColumn>& columns) {
  std::string line;
  for (const auto& column : columns) {
    if (!line.empty())
      line += ',';
    line += fmt::format("{} [{}]", column.name, column.unit.empty() ? "-" : column.unit);
  }
  return line;
}

}  // namespace

SeriesWriter::SeriesWriter(const std::filesystem::path& file, std::vector<SeriesColumn> columns)
    : file_(file), columns_(std::move(columns)) {
  check_columns(columns_);
  out_.open(file_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    throw RunError("cannot open '" + file_.string() + "' for writing");
  }
  flush_line(header_line(columns_));
}

void SeriesWriter::write_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("series row has {} values for {} columns in '{}'",
                                            values.size(), columns_.size(), file_.string()));
  }
  flush_line(fmt::format("{:.10g}", fmt::join(values, ",")));
}

void SeriesWriter::flush_line(const std::string& line) {
  out_ << line << '\n';
  out_.flush();
  if (!out_) {
    throw RunError("failed writing '" + file_.string() + "'");
  }
}

}  // namespace partimix::io
