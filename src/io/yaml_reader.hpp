#pragma once
// A small validating reader over yaml-cpp nodes (DESIGN.md, "Inputs, outputs, errors"). A Reader
// stands on one map of a document; each getter names a key, checks its type and range, and
// records the value used (default included) in a JSON tree. done() then rejects every key no
// getter asked for, listing those that were. Every problem is an InputError naming the file,
// line, column and dotted key path (`fluid.regions[1].max`), or "--set" for overridden keys.
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/vec.hpp"

namespace partimix::io {

// A lower bound on a number: value > limit when strict, value >= limit otherwise.
struct Bound {
  double limit = -std::numeric_limits<double>::infinity();
  bool strict = false;
};
inline constexpr Bound kPositive{0.0, true};
inline constexpr Bound kNonNegative{0.0, false};
constexpr Bound at_least(double limit) {
  return {limit, false};
}

// What every Reader of one document shares.
struct ReadContext {
  std::string file;
  std::vector<std::string> overridden;  // key paths set by --set; errors there name "--set"
  nlohmann::json resolved;              // every key read, with the value used
  std::map<std::string, InputLocation> locations;  // where each key and list item read was

  // Where an error about the node at `key_path` points: "--set" when --set wrote or created
  // that node, otherwise the file at `mark` (line 0 when the node has no mark).
  InputLocation locate(const std::string& key_path, const YAML::Mark& mark) const;
};

// Parses a YAML file; a missing, unreadable or malformed file is an InputError.
YAML::Node load_yaml_file(const std::string& path);

class Reader {
 public:
  // The root of a document, which must be a map.
  Reader(const YAML::Node& root, std::shared_ptr<ReadContext> context);

  // T is double, int, bool or std::string; the bound applies to numbers.
  template <class T>
  T required(const std::string& key, Bound bound = {});
  template <class T>
  T optional(const std::string& key, T fallback, Bound bound = {});
  // "auto" (the default) gives nullopt; otherwise a number within the bound.
  template <class T>
  std::optional<T> automatic(const std::string& key, Bound bound = {});

  // A string that must be one of `allowed`.
  std::string required_choice(const std::string& key, const std::vector<std::string>& allowed);
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed);
  // A list of strings, each one of `allowed`; default empty.
  std::vector<std::string> choices(const std::string& key, const std::vector<std::string>& allowed);

  // One name or a list of distinct names, each one of `allowed`; required.
  std::vector<std::string> required_choices(const std::string& key,
                                            const std::vector<std::string>& allowed);

  // A list of exactly `dimensions` numbers; the components beyond are 0.
  Vec3 vector(const std::string& key, int dimensions);
  Vec3 vector(const std::string& key, int dimensions, const Vec3& fallback);

  // Whether this map holds `key`, with any value; asking does not count as reading the key.
  bool contains(const std::string& key) const;

  Reader map(const std::string& key);
  Reader optional_map(const std::string& key);  // absent: an empty map, so defaults are recorded
  std::vector<Reader> list(const std::string& key);           // a non-empty list of maps
  std::vector<Reader> optional_list(const std::string& key);  // default empty

  // An error about `key` (at its value, or at this map when the key is absent).
  [[nodiscard]] InputError error(const std::string& key, const std::string& message) const;
  // Rejects the keys of this map that no getter asked for.
  void done() const;

 private:
  Reader(const YAML::Node& node, std::shared_ptr<ReadContext> context, std::string path,
         nlohmann::json::json_pointer pointer);
  YAML::Node find(const std::string& key);
  YAML::Node find_required(const std::string& key);
  Reader child(const YAML::Node& node, const std::string& path,
               const nlohmann::json::json_pointer& pointer) const;
  std::vector<Reader> items(const YAML::Node& node, const std::string& key);
  std::string path_of(const std::string& key) const;
  InputError error_at(const YAML::Node& node, const std::string& path,
                      const std::string& message) const;
  void record(const std::string& key, nlohmann::json value);
  void remember(const YAML::Node& node, const std::string& path) const;
  template <class T>
  T decode(const YAML::Node& node, const std::string& path, Bound bound,
           const std::string& expected) const;
  std::string pick(const YAML::Node& node, const std::string& path,
                   const std::vector<std::string>& allowed) const;
  Vec3 components(const YAML::Node& node, const std::string& path, int dimensions) const;

  YAML::Node node_;
  std::shared_ptr<ReadContext> context_;
  std::string path_;
  nlohmann::json::json_pointer pointer_;
  std::vector<std::string> known_;
};

}  // namespace partimix::io
