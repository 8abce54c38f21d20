#include "io/series_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

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
  return line + '\n';
}

// Writes all of `text`, continuing after a partial write or an interrupted call.
bool write_all(int descriptor, std::string_view text) {
  while (!text.empty()) {
    const ssize_t written = ::write(descriptor, text.data(), text.size());
    if (written < 0 && errno == EINTR)
      continue;
    if (written <= 0)
      return false;
    text.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

}  // namespace

SeriesWriter::SeriesWriter(const std::filesystem::path& file, std::vector<SeriesColumn> columns,
                           std::span<const double> rows)
    : file_(file), columns_(std::move(columns)) {
  check_columns(columns_);
  if (columns_.empty())
    throw std::invalid_argument("a series needs at least one column");
  if (rows.size() % columns_.size() != 0)
    throw std::invalid_argument("series rows must fill whole rows of the columns");
  std::string content = header_line(columns_);
  for (std::size_t first = 0; first < rows.size(); first += columns_.size())
    content += format_row(rows.subspan(first, columns_.size()));
  write_atomically(file_, [&content](std::ostream& out) { out << content; });
  descriptor_ = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (descriptor_ < 0)
    throw RunError("cannot open '" + file_.string() + "' for writing: " + std::strerror(errno));
}

SeriesWriter::~SeriesWriter() {
  if (descriptor_ >= 0)
    ::close(descriptor_);
}

void SeriesWriter::write_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("series row has {} values for {} columns in '{}'",
                                            values.size(), columns_.size(), file_.string()));
  }
  if (!write_all(descriptor_, format_row(values)))
    throw RunError("failed writing '" + file_.string() + "': " + std::strerror(errno));
}

std::string SeriesWriter::format_row(std::span<const double> values) const {
  return fmt::format("{:.10g}\n", fmt::join(values, ","));
}

}  // namespace partimix::io
