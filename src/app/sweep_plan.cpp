#include "app/sweep_plan.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "core/error.hpp"

namespace partimix::app {
namespace {

InputError vary_error(const std::string& key, const std::string& message) {
  return InputError({"--vary", 0, 0, key}, message);
}

std::string trimmed(std::string_view text) {
  const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!text.empty() && space(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  while (!text.empty() && space(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return std::string(text);
}

// The pieces of `list` between the commas that sit outside [] and {}.
std::vector<std::string> split_values(const std::string& list) {
  std::vector<std::string> values;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i] == '[' || list[i] == '{')
      ++depth;
    else if (list[i] == ']' || list[i] == '}')
      --depth;
    else if (list[i] == ',' && depth == 0) {
      values.push_back(trimmed(std::string_view(list).substr(start, i - start)));
      start = i + 1;
    }
  }
  values.push_back(trimmed(std::string_view(list).substr(start)));
  return values;
}

SweepAxis parse_axis(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos)
    throw vary_error(text, "expected KEY=v1,v2,... (no '=')");
  SweepAxis axis{trimmed(std::string_view(text).substr(0, equals)), {}};
  if (axis.key.empty())
    throw vary_error(text, "empty key; expected KEY=v1,v2,...");
  const std::string list = text.substr(equals + 1);
  if (trimmed(list).empty())
    throw vary_error(axis.key, "no values; expected KEY=v1,v2,...");
  axis.values = split_values(list);
  if (std::any_of(axis.values.begin(), axis.values.end(),
                  [](const std::string& value) { return value.empty(); })) {
    throw vary_error(axis.key, "empty value in '" + list + "'; expected v1,v2,...");
  }
  return axis;
}

}  // namespace

std::vector<SweepAxis> parse_sweep_axes(const std::vector<std::string>& texts) {
  std::vector<SweepAxis> axes;
  for (const std::string& text : texts) {
    SweepAxis axis = parse_axis(text);
    const bool repeated = std::any_of(
        axes.begin(), axes.end(), [&](const SweepAxis& other) { return other.key == axis.key; });
    if (repeated)
      throw vary_error(axis.key, "varied twice; give all its values in one --vary");
    axes.push_back(std::move(axis));
  }
  return axes;
}

std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes) {
  std::vector<SweepPoint> points{SweepPoint{}};
  for (const SweepAxis& axis : axes) {
    std::vector<SweepPoint> longer;
    for (const SweepPoint& point : points) {
      for (const std::string& value : axis.values) {
        longer.push_back(point);
        longer.back().push_back(value);
      }
    }
    points = std::move(longer);
  }
  return points;
}

std::vector<std::string> point_overrides(const std::vector<SweepAxis>& axes,
                                         const SweepPoint& point) {
  std::vector<std::string> overrides;
  for (std::size_t i = 0; i < axes.size(); ++i)
    overrides.push_back(axes[i].key + "=" + point[i]);
  return overrides;
}

}  // namespace partimix::app
