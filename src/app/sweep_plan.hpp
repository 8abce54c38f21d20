#pragma once
// The runs of `partimix sweep` (docs/sweeps.md): each `--vary KEY=v1,v2,...` is an axis, and
// the sweep runs every combination of one value per axis, the cartesian product of the axes.
#include <string>
#include <vector>

namespace partimix::app {

struct SweepAxis {
  std::string key;                  // a key path, as --set takes it
  std::vector<std::string> values;  // YAML texts, as --set takes them
};

// One value per axis, in the order of the axes.
using SweepPoint = std::vector<std::string>;

// Reads each "KEY=v1,v2,...". Values are split at the commas outside brackets and braces, so
// that `gravity=[0,-9.81],[0,-4.9]` gives two values. Throws InputError (file "--vary", the
// key as key path) on a text without '=', an empty key, an empty value or a key varied twice.
std::vector<SweepAxis> parse_sweep_axes(const std::vector<std::string>& texts);

// Every combination of one value per axis; the last axis varies fastest.
std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes);

// The overrides ("KEY=value", one per axis) that make the case of `point`.
std::vector<std::string> point_overrides(const std::vector<SweepAxis>& axes,
                                         const SweepPoint& point);

}  // namespace partimix::app
