#include "io/yaml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <type_traits>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace partimix::io {
namespace {

// Levenshtein distance, to tell a misspelt key from a missing one.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

std::string describe(const YAML::Node& node) {
  if (!node.IsDefined()) {
    return "nothing";
  }
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return fmt::format("'{}'", node.Scalar());
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "nothing";
  }
}

template <class T>
std::string kind();
template <>
std::string kind<double>() {
  return "a number";
}
template <>
std::string kind<int>() {
  return "an integer";
}
template <>
std::string kind<bool>() {
  return "true or false";
}
template <>
std::string kind<std::string>() {
  return "a string";
}

std::string one_of(const std::vector<std::string>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

bool within(double value, Bound bound) {
  return bound.strict ? value > bound.limit : value >= bound.limit;
}

// Whether `path` is `prefix` or a key path inside it.
bool is_under(const std::string& path, const std::string& prefix) {
  return path == prefix || path.starts_with(prefix + ".") || path.starts_with(prefix + "[");
}

bool absent(const YAML::Node& node) {
  return !node.IsDefined() || node.IsNull();
}

std::string item_path(const std::string& path, std::size_t index) {
  return fmt::format("{}[{}]", path, index);
}

nlohmann::json to_json(const Vec3& v, int dimensions) {
  nlohmann::json values = nlohmann::json::array();
  for (int axis = 0; axis < dimensions; ++axis) {
    values.push_back(v[axis]);
  }
  return values;
}

}  // namespace

InputLocation ReadContext::locate(const std::string& key_path, const YAML::Mark& mark) const {
  const auto set_here = [&key_path](const std::string& set) { return is_under(key_path, set); };
  const auto on_the_way = [&key_path](const std::string& set) { return is_under(set, key_path); };
  const bool made_by_set =
      mark.is_null() && std::any_of(overridden.begin(), overridden.end(), on_the_way);
  if (made_by_set || std::any_of(overridden.begin(), overridden.end(), set_here)) {
    return {"--set", 0, 0, key_path};
  }
  if (mark.is_null()) {
    return {file, 0, 0, key_path};
  }
  return {file, mark.line + 1, mark.column + 1, key_path};
}

YAML::Node load_yaml_file(const std::string& path) {
  std::error_code ignored;
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path, ignored) || !in) {
    throw InputError({path, 0, 0, ""}, "cannot read the case file: no such readable file");
  }
  try {
    return YAML::Load(in);
  } catch (const YAML::ParserException& ex) {
    throw InputError({path, ex.mark.line + 1, ex.mark.column + 1, ""}, "malformed YAML: " + ex.msg);
  }
}

Reader::Reader(const YAML::Node& root, std::shared_ptr<ReadContext> context)
    : Reader(root, std::move(context), "", nlohmann::json::json_pointer()) {
  if (!root.IsMap()) {
    throw error_at(root, "", "expected a map of case keys, got " + describe(root));
  }
}

Reader::Reader(const YAML::Node& node, std::shared_ptr<ReadContext> context, std::string path,
               nlohmann::json::json_pointer pointer)
    : node_(node),
      context_(std::move(context)),
      path_(std::move(path)),
      pointer_(std::move(pointer)) {}

template <class T>
T Reader::required(const std::string& key, Bound bound) {
  const T value = decode<T>(find_required(key), path_of(key), bound, kind<T>());
  record(key, value);
  return value;
}

template <class T>
T Reader::optional(const std::string& key, T fallback, Bound bound) {
  const YAML::Node node = find(key);
  const T value = node.IsDefined() ? decode<T>(node, path_of(key), bound, kind<T>()) : fallback;
  record(key, value);
  return value;
}

template <class T>
std::optional<T> Reader::automatic(const std::string& key, Bound bound) {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || (node.IsScalar() && node.Scalar() == "auto")) {
    record(key, "auto");
    return std::nullopt;
  }
  const T value = decode<T>(node, path_of(key), bound, "\"auto\" or " + kind<T>());
  record(key, value);
  return value;
}

std::string Reader::required_choice(const std::string& key,
                                    const std::vector<std::string>& allowed) {
  const std::string value = pick(find_required(key), path_of(key), allowed);
  record(key, value);
  return value;
}

std::string Reader::choice(const std::string& key, const std::string& fallback,
                           const std::vector<std::string>& allowed) {
  const YAML::Node node = find(key);
  const std::string value = node.IsDefined() ? pick(node, path_of(key), allowed) : fallback;
  record(key, value);
  return value;
}

std::vector<std::string> Reader::choices(const std::string& key,
                                         const std::vector<std::string>& allowed) {
  const YAML::Node node = find(key);
  std::vector<std::string> values;
  if (!absent(node)) {
    if (!node.IsSequence()) {
      throw error_at(node, path_of(key),
                     fmt::format("expected a list of names from: {}; got {}", one_of(allowed),
                                 describe(node)));
    }
    for (std::size_t i = 0; i < node.size(); ++i) {
      values.push_back(pick(node[i], item_path(path_of(key), i), allowed));
    }
  }
  record(key, values);
  return values;
}

std::vector<std::string> Reader::required_choices(const std::string& key,
                                                  const std::vector<std::string>& allowed) {
  const YAML::Node node = find_required(key);
  if (!node.IsSequence()) {
    const std::string value = pick(node, path_of(key), allowed);
    record(key, value);
    return {value};
  }
  if (node.size() == 0)
    throw error_at(node, path_of(key), "expected at least one name from: " + one_of(allowed));
  std::vector<std::string> values;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = item_path(path_of(key), i);
    const std::string value = pick(node[i], path, allowed);
    if (std::find(values.begin(), values.end(), value) != values.end())
      throw error_at(node[i], path, fmt::format("'{}' appears twice", value));
    values.push_back(value);
  }
  record(key, values);
  return values;
}

Vec3 Reader::vector(const std::string& key, int dimensions) {
  const Vec3 value = components(find_required(key), path_of(key), dimensions);
  record(key, to_json(value, dimensions));
  return value;
}

Vec3 Reader::vector(const std::string& key, int dimensions, const Vec3& fallback) {
  const YAML::Node node = find(key);
  const Vec3 value = node.IsDefined() ? components(node, path_of(key), dimensions) : fallback;
  record(key, to_json(value, dimensions));
  return value;
}

bool Reader::contains(const std::string& key) const {
  return std::as_const(node_)[key].IsDefined();
}

Reader Reader::map(const std::string& key) {
  const YAML::Node node = find_required(key);
  if (!node.IsMap()) {
    throw error_at(node, path_of(key), "expected a map, got " + describe(node));
  }
  return child(node, path_of(key), pointer_ / key);
}

Reader Reader::optional_map(const std::string& key) {
  const YAML::Node node = find(key);
  return absent(node) ? child(YAML::Node(YAML::NodeType::Map), path_of(key), pointer_ / key)
                      : map(key);
}

std::vector<Reader> Reader::list(const std::string& key) {
  const YAML::Node node = find_required(key);
  std::vector<Reader> readers = items(node, key);
  if (readers.empty()) {
    throw error_at(node, path_of(key), "must have at least one item");
  }
  return readers;
}

std::vector<Reader> Reader::optional_list(const std::string& key) {
  const YAML::Node node = find(key);
  if (absent(node)) {
    record(key, nlohmann::json::array());
    return {};
  }
  return items(node, key);
}

InputError Reader::error(const std::string& key, const std::string& message) const {
  const YAML::Node node = std::as_const(node_)[key];
  return error_at(node.IsDefined() ? node : node_, path_of(key), message);
}

void Reader::done() const {
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
      throw error_at(entry.first, path_of(key),
                     fmt::format("unknown key '{}'; expected one of: {}", key, one_of(known_)));
    }
  }
}

YAML::Node Reader::find(const std::string& key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
    known_.push_back(key);
  }
  const YAML::Node node = std::as_const(node_)[key];
  remember(node, path_of(key));
  return node;
}

// Where the set-up of the case (after reading) finds a problem with the key at `path`.
void Reader::remember(const YAML::Node& node, const std::string& path) const {
  if (node.IsDefined())
    context_->locations.insert_or_assign(path, context_->locate(path, node.Mark()));
}

YAML::Node Reader::find_required(const std::string& key) {
  const YAML::Node node = find(key);
  if (!node.IsDefined()) {
    const std::size_t near = key.size() <= 4 ? 1 : 2;
    for (const auto& entry : node_) {
      const std::string written = entry.first.Scalar();
      const bool read = std::find(known_.begin(), known_.end(), written) != known_.end();
      if (!read && edit_distance(written, key) <= near) {
        throw error_at(entry.first, path_of(written),
                       fmt::format("unknown key '{}'; did you mean '{}'?", written, key));
      }
    }
    throw error_at(node_, path_of(key), fmt::format("missing required key '{}'", key));
  }
  return node;
}

Reader Reader::child(const YAML::Node& node, const std::string& path,
                     const nlohmann::json::json_pointer& pointer) const {
  return Reader(node, context_, path, pointer);
}

std::vector<Reader> Reader::items(const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence()) {
    throw error_at(node, path_of(key), "expected a list, got " + describe(node));
  }
  record(key, nlohmann::json::array());
  std::vector<Reader> readers;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    if (!item.IsMap()) {
      throw error_at(item, item_path(path_of(key), i), "expected a map, got " + describe(item));
    }
    remember(item, item_path(path_of(key), i));
    readers.push_back(child(item, item_path(path_of(key), i), pointer_ / key / i));
  }
  return readers;
}

std::string Reader::path_of(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

InputError Reader::error_at(const YAML::Node& node, const std::string& path,
                            const std::string& message) const {
  const YAML::Mark mark = node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
  return InputError(context_->locate(path, mark), message);
}

void Reader::record(const std::string& key, nlohmann::json value) {
  context_->resolved[pointer_ / key] = std::move(value);
}

template <class T>
T Reader::decode(const YAML::Node& node, const std::string& path, Bound bound,
                 const std::string& expected) const {
  T value{};
  if (!node.IsScalar() || !YAML::convert<T>::decode(node, value)) {
    throw error_at(node, path, fmt::format("expected {}, got {}", expected, describe(node)));
  }
  if constexpr (std::is_same_v<T, double>) {
    if (!std::isfinite(value)) {
      throw error_at(node, path, "expected a finite number, got " + describe(node));
    }
  }
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    if (!within(value, bound)) {
      throw error_at(node, path,
                     fmt::format("must be {} {}, got {}", bound.strict ? ">" : ">=", bound.limit,
                                 node.Scalar()));
    }
  }
  return value;
}

std::string Reader::pick(const YAML::Node& node, const std::string& path,
                         const std::vector<std::string>& allowed) const {
  const auto value = decode<std::string>(node, path, {}, "one of: " + one_of(allowed));
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
    throw error_at(node, path,
                   fmt::format("unknown value '{}'; expected one of: {}", value, one_of(allowed)));
  }
  return value;
}

Vec3 Reader::components(const YAML::Node& node, const std::string& path, int dimensions) const {
  if (!node.IsSequence()) {
    throw error_at(
        node, path,
        fmt::format("expected a list of {} numbers, got {}", dimensions, describe(node)));
  }
  if (node.size() != static_cast<std::size_t>(dimensions)) {
    throw error_at(node, path,
                   fmt::format("expected {} components (dimensions is {}), got {}", dimensions,
                               dimensions, node.size()));
  }
  Vec3 value = Vec3::Zero();
  for (int axis = 0; axis < dimensions; ++axis) {
    value[axis] = decode<double>(node[axis], item_path(path, static_cast<std::size_t>(axis)), {},
                                 kind<double>());
  }
  return value;
}

template double Reader::required<double>(const std::string&, Bound);
template int Reader::required<int>(const std::string&, Bound);
template bool Reader::required<bool>(const std::string&, Bound);
template std::string Reader::required<std::string>(const std::string&, Bound);
template double Reader::optional<double>(const std::string&, double, Bound);
template int Reader::optional<int>(const std::string&, int, Bound);
template bool Reader::optional<bool>(const std::string&, bool, Bound);
template std::string Reader::optional<std::string>(const std::string&, std::string, Bound);
template std::optional<double> Reader::automatic<double>(const std::string&, Bound);
template std::optional<int> Reader::automatic<int>(const std::string&, Bound);

}  // namespace partimix::io
