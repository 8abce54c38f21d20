#pragma once
// Command-line overrides of case keys (`--set a.b.c=value`, docs/case-reference.md). Each is
// applied to the YAML tree before validation, so an overridden value is checked like any other.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace partimix::io {

// Sets each "path=value" in `root`: the path is dotted keys with optional list indices
// (`fluid.regions[0].max`), the value is parsed as YAML. Missing maps along the path are
// created; an index may name an existing item or the one just past the end (appending). A null
// value (`null`, `~` or nothing) removes the key from its map instead.
// Returns the key paths set, written as errors write them. Throws InputError with file "--set".
std::vector<std::string> apply_overrides(YAML::Node& root,
                                         const std::vector<std::string>& overrides);

}  // namespace partimix::io
