#include "io/overrides.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::io {
namespace {

// One step along a key path: a map key, or a list index.
struct Step {
  std::string key;
  std::optional<std::size_t> index;
};

InputError set_error(const std::string& path, const std::string& message) {
  return InputError({"--set", 0, 0, path}, message);
}

std::string render(const std::vector<Step>& steps, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count; ++i) {
    if (steps[i].index) {
      text += fmt::format("[{}]", *steps[i].index);
    } else {
      text += (i == 0 ? "" : ".") + steps[i].key;
    }
  }
  return text;
}

Step read_key(const std::string& path, std::size_t& at) {
  const std::size_t end = std::min(path.find_first_of(".[", at), path.size());
  Step step{path.substr(at, end - at), std::nullopt};
  if (step.key.empty()) {
    throw set_error(path, "empty key in the key path; expected keys joined by '.', e.g. a.b[0].c");
  }
  at = end;
  return step;
}

Step read_index(const std::string& path, std::size_t& at) {
  const std::size_t close = path.find(']', at);
  const std::string digits =
      close == std::string::npos ? std::string() : path.substr(at + 1, close - at - 1);
  if (digits.empty() || !std::all_of(digits.begin(), digits.end(),
                                     [](unsigned char c) { return std::isdigit(c) != 0; })) {
    throw set_error(path, "malformed list index; expected [n] with n a whole number >= 0");
  }
  std::size_t index = 0;
  const auto [end, status] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (status != std::errc() || end != digits.data() + digits.size())
    throw set_error(path, fmt::format("list index [{}] is too large", digits));
  at = close + 1;
  return Step{"", index};
}

std::vector<Step> parse_path(const std::string& path) {
  std::size_t at = 0;
  std::vector<Step> steps{read_key(path, at)};
  while (at < path.size()) {
    if (path[at] == '[') {
      steps.push_back(read_index(path, at));
    } else {
      ++at;
      steps.push_back(read_key(path, at));
    }
  }
  return steps;
}

// How a message names the node the first `count` steps lead to.
std::string name_of(const std::vector<Step>& steps, std::size_t count) {
  return count == 0 ? std::string("the case file") : fmt::format("'{}'", render(steps, count));
}

// The node that `steps[i]` names inside `current`, created when missing.
YAML::Node descend(YAML::Node current, const std::vector<Step>& steps, std::size_t i) {
  const Step& step = steps[i];
  if (!step.index) {
    if (!current.IsDefined() || current.IsNull()) {
      current = YAML::Node(YAML::NodeType::Map);
    }
    if (!current.IsMap()) {
      throw set_error(render(steps, i + 1), name_of(steps, i) + " is not a map");
    }
    return current[step.key];
  }
  if (!current.IsSequence()) {
    throw set_error(render(steps, i + 1), name_of(steps, i) + " is not a list");
  }
  if (*step.index > current.size()) {
    throw set_error(render(steps, i + 1),
                    fmt::format("list index out of range; {} allows 0 to {} ({} appends an item)",
                                name_of(steps, i), current.size(), current.size()));
  }
  if (*step.index == current.size()) {
    current.push_back(YAML::Node(YAML::NodeType::Null));
  }
  return current[*step.index];
}

// `key.path=null` (or `~`, or nothing after '='): the key is removed from its map, so that its
// default holds or another key can take its place. A key that is not there is no error.
std::string remove_key(YAML::Node& root, const std::vector<Step>& steps) {
  const std::string path = render(steps, steps.size());
  if (steps.back().index)
    throw set_error(path, "null removes a key of a map, not an item of a list");
  YAML::Node parent = root;
  for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
    const YAML::Node next = steps[i].index ? (parent.IsSequence() && *steps[i].index < parent.size()
                                                  ? parent[*steps[i].index]
                                                  : YAML::Node())
                                           : (parent.IsMap() ? parent[steps[i].key] : YAML::Node());
    if (!next.IsDefined())
      return path;
    parent.reset(next);
  }
  if (parent.IsMap())
    parent.remove(steps.back().key);
  return path;
}

YAML::Node parse_value(const std::string& path, const std::string& text) {
  try {
    const YAML::Node value = YAML::Load(text);
    return value.IsNull() ? YAML::Node(YAML::NodeType::Null) : value;
  } catch (const YAML::ParserException& ex) {
    throw set_error(path, fmt::format("cannot parse the value '{}': {}", text, ex.msg));
  }
}

std::string apply_one(YAML::Node& root, const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos) {
    throw set_error(text, "expected key.path=value");
  }
  const std::string raw_path = text.substr(0, equals);
  if (raw_path.empty()) {
    throw set_error(raw_path, fmt::format("empty key path in '{}'; expected key.path=value", text));
  }
  const std::vector<Step> steps = parse_path(raw_path);
  const std::string path = render(steps, steps.size());
  const YAML::Node value = parse_value(path, text.substr(equals + 1));
  if (value.IsNull())
    return remove_key(root, steps);
  YAML::Node target = root;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    target.reset(descend(target, steps, i));
  }
  target = value;
  return path;
}

}  // namespace

std::vector<std::string> apply_overrides(YAML::Node& root,
                                         const std::vector<std::string>& overrides) {
  if (!overrides.empty() && root.IsNull()) {
    root = YAML::Node(YAML::NodeType::Map);
  }
  std::vector<std::string> paths;
  for (const std::string& text : overrides) {
    paths.push_back(apply_one(root, text));
  }
  return paths;
}

}  // namespace partimix::io
