#include "core/state_archive.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>
#include <utility>

namespace partimix {
namespace {

bool is_segment_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.' || c == '+' || c == '-';
}

// "." would name the current group in an HDF5 path; ".." is refused with it to avoid surprises.
bool is_valid_segment(std::string_view segment) {
  return !segment.empty() && segment != "." && segment != ".." &&
         std::all_of(segment.begin(), segment.end(), is_segment_char);
}

std::string kind_name(StateArchive::Kind kind) {
  switch (kind) {
    case StateArchive::Kind::doubles:
      return "doubles";
    case StateArchive::Kind::integers:
      return "integers";
    case StateArchive::Kind::text:
      return "text";
  }
  return "?";
}

std::string describe(const StateArchive::Entry& entry) {
  if (entry.kind == StateArchive::Kind::text) {
    return fmt::format("a text of {} bytes", entry.text.size());
  }
  return fmt::format("{} x {} {}", entry.rows(), entry.columns, kind_name(entry.kind));
}

std::string describe_wanted(StateArchive::Kind kind, std::size_t columns) {
  if (kind == StateArchive::Kind::text) {
    return "a text";
  }
  return fmt::format("{}-column {}", columns, kind_name(kind));
}

void check_shape(const std::string& path, std::size_t size, std::size_t columns) {
  if (columns == 0) {
    throw std::invalid_argument("state '" + path + "': columns must be at least 1");
  }
  if (size % columns != 0) {
    throw std::invalid_argument(
        fmt::format("state '{}': {} values do not fill rows of {} columns", path, size, columns));
  }
}

}  // namespace

std::size_t StateArchive::Entry::rows() const {
  switch (kind) {
    case Kind::doubles:
      return doubles.size() / columns;
    case Kind::integers:
      return integers.size() / columns;
    case Kind::text:
      return 1;
  }
  return 0;
}

bool StateArchive::is_valid_path(const std::string& path) {
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = path.find('/', begin);
    const std::string_view segment =
        std::string_view(path).substr(begin, end == std::string::npos ? end : end - begin);
    if (!is_valid_segment(segment)) {
      return false;
    }
    if (end == std::string::npos) {
      return true;
    }
    begin = end + 1;
  }
}

void StateArchive::put_doubles(const std::string& path, std::span<const double> values,
                               std::size_t columns) {
  check_shape(path, values.size(), columns);
  Entry entry{Kind::doubles, columns, {values.begin(), values.end()}, {}, {}};
  put(path, std::move(entry));
}

void StateArchive::put_integers(const std::string& path, std::span<const std::int64_t> values,
                                std::size_t columns) {
  check_shape(path, values.size(), columns);
  Entry entry{Kind::integers, columns, {}, {values.begin(), values.end()}, {}};
  put(path, std::move(entry));
}

void StateArchive::put_text(const std::string& path, std::string text) {
  put(path, Entry{Kind::text, 1, {}, {}, std::move(text)});
}

void StateArchive::put_scalar(const std::string& path, double value) {
  put_doubles(path, std::span<const double>(&value, 1));
}

void StateArchive::put_vectors(const std::string& path, std::span<const Vec3> values) {
  std::vector<double> flat;
  flat.reserve(3 * values.size());
  for (const Vec3& v : values) {
    flat.insert(flat.end(), {v.x(), v.y(), v.z()});
  }
  put(path, Entry{Kind::doubles, 3, std::move(flat), {}, {}});
}

void StateArchive::put(const std::string& path, Entry entry) {
  if (!is_valid_path(path)) {
    throw std::invalid_argument("state path '" + path +
                                "' is not segments of [A-Za-z0-9_.+-] joined by '/'");
  }
  // In the file an entry is a dataset and a path prefix a group: one name cannot be both.
  for (std::size_t slash = path.find('/'); slash != std::string::npos;
       slash = path.find('/', slash + 1)) {
    if (entries_.count(path.substr(0, slash)) > 0) {
      throw std::invalid_argument("state path '" + path + "' lies under the entry '" +
                                  path.substr(0, slash) + "'");
    }
  }
  const auto below = entries_.lower_bound(path + "/");
  if (below != entries_.end() && below->first.starts_with(path + "/")) {
    throw std::invalid_argument("state path '" + path + "' would hide the entry '" + below->first +
                                "' under it");
  }
  entries_.insert_or_assign(path, std::move(entry));
}

const StateArchive::Entry& StateArchive::find(const std::string& path, Kind kind,
                                              std::size_t columns) const {
  const auto it = entries_.find(path);
  if (it == entries_.end()) {
    throw StateError("state '" + path + "': expected " + describe_wanted(kind, columns) +
                     ", found no such entry");
  }
  const Entry& entry = it->second;
  if (entry.kind != kind || entry.columns != columns) {
    throw StateError("state '" + path + "': expected " + describe_wanted(kind, columns) +
                     ", found " + describe(entry));
  }
  return entry;
}

std::span<const double> StateArchive::doubles(const std::string& path, std::size_t columns) const {
  return find(path, Kind::doubles, columns).doubles;
}

std::span<const std::int64_t> StateArchive::integers(const std::string& path,
                                                     std::size_t columns) const {
  return find(path, Kind::integers, columns).integers;
}

const std::string& StateArchive::text(const std::string& path) const {
  return find(path, Kind::text, 1).text;
}

double StateArchive::scalar(const std::string& path) const {
  const Entry& entry = find(path, Kind::doubles, 1);
  if (entry.doubles.size() != 1) {
    throw StateError("state '" + path + "': expected a scalar (1 x 1 doubles), found " +
                     describe(entry));
  }
  return entry.doubles.front();
}

std::vector<Vec3> StateArchive::vectors(const std::string& path) const {
  const std::vector<double>& flat = find(path, Kind::doubles, 3).doubles;
  std::vector<Vec3> values(flat.size() / 3);
  for (std::size_t i = 0; i < values.size(); ++i) {
    values[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  }
  return values;
}

std::vector<std::string> StateArchive::paths() const {
  std::vector<std::string> sorted;
  sorted.reserve(entries_.size());
  for (const auto& [path, entry] : entries_) {
    sorted.push_back(path);
  }
  return sorted;
}

}  // namespace partimix
