#pragma once
// The keys `partimix optimise` searches over (docs/design-loop.md): each `--vary KEY=lo:hi` a
// case key path, as --set takes it, and its bounds.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace partimix::app {

struct DesignVariable {
  std::string key;
  double lower = 0.0;
  double upper = 0.0;
};

// Reads each "KEY=lo:hi". Throws InputError (file "--vary", the key as key path) on a text
// without '=' or ':', numbers that do not read whole or are not finite, lo >= hi, or a key given
// twice.
std::vector<DesignVariable> parse_design_variables(const std::vector<std::string>& texts);

// The value of `key` (a key path such as walls[0].blades.helix_angle) in the case's resolved
// keys when it is a number within the variable's bounds; else the middle of the bounds.
double start_value(const DesignVariable& variable, const nlohmann::json& resolved);

// The override "KEY=value" of each variable at `x`, the value at full precision (17 digits), so
// that the run sees exactly the point the search asked for.
std::vector<std::string> design_overrides(const std::vector<DesignVariable>& variables,
                                          const std::vector<double>& x);

}  // namespace partimix::app
