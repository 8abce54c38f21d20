#include "app/design_variables.hpp"

#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::app {
namespace {

InputError vary_error(const std::string& key, const std::string& message) {
  return InputError({"--vary", 0, 0, key}, message);
}

double read_number(const std::string& text, const std::string& key) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw vary_error(key, fmt::format("'{}' is not a finite number", text));
  return value;
}

// "walls[0].blades.helix_angle" as the JSON pointer "/walls/0/blades/helix_angle".
nlohmann::json::json_pointer pointer_of(const std::string& key) {
  std::string pointer;
  for (char c : key) {
    if (c == '.' || c == '[')
      pointer += '/';
    else if (c != ']')
      pointer += c;
  }
  return nlohmann::json::json_pointer("/" + pointer);
}

}  // namespace

std::vector<DesignVariable> parse_design_variables(const std::vector<std::string>& texts) {
  std::vector<DesignVariable> variables;
  std::set<std::string> seen;
  for (const std::string& text : texts) {
    const std::size_t equals = text.find('=');
    const std::string key = text.substr(0, equals);
    if (equals == std::string::npos || key.empty())
      throw vary_error(key, fmt::format("'{}' is not KEY=lo:hi", text));
    const std::string range = text.substr(equals + 1);
    const std::size_t colon = range.find(':');
    if (colon == std::string::npos)
      throw vary_error(key, fmt::format("'{}' is not lo:hi", range));
    DesignVariable variable{key, read_number(range.substr(0, colon), key),
                            read_number(range.substr(colon + 1), key)};
    if (!(variable.upper > variable.lower))
      throw vary_error(key, fmt::format("the upper bound must exceed the lower ({})", range));
    if (!seen.insert(key).second)
      throw vary_error(key, "this key is varied twice");
    variables.push_back(variable);
  }
  return variables;
}

double start_value(const DesignVariable& variable, const nlohmann::json& resolved) {
  const double middle = 0.5 * (variable.lower + variable.upper);
  try {
    const nlohmann::json& value = resolved.at(pointer_of(variable.key));
    if (value.is_number()) {
      const double x = value.get<double>();
      if (x >= variable.lower && x <= variable.upper)
        return x;
    }
  } catch (const nlohmann::json::exception&) {
    return middle;
  }
  return middle;
}

std::vector<std::string> design_overrides(const std::vector<DesignVariable>& variables,
                                          const std::vector<double>& x) {
  std::vector<std::string> overrides;
  for (std::size_t k = 0; k < variables.size(); ++k)
    overrides.push_back(fmt::format("{}={:.17g}", variables[k].key, x[k]));
  return overrides;
}

}  // namespace partimix::app
