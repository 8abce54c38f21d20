#pragma once
// Bound-constrained minimisation without derivatives through NLopt (docs/design-loop.md): the
// design loop's search over a few case keys, each evaluation a whole simulation. The variables
// are scaled to the unit box [0, 1]^n before NLopt sees them, so that one step and one tolerance
// serve keys of any unit; the first step is a quarter of each range. NLopt is deterministic: the
// same objective values give the same sequence of points, which is what makes a search resumable
// from a cache of evaluated points.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace partimix {

struct SearchSettings {
  std::string algorithm = "bobyqa";  // bobyqa | cobyla | neldermead (NLopt's LN_ algorithms)
  int max_evaluations = 20;
  std::optional<double> stop_value;  // stop once a value is at or below it
  double x_tolerance = 1e-3;         // stop when a step changes the point by less (unit box)
};

struct SearchResult {
  std::vector<double> best;  // in the keys' own units
  double value = 0.0;
  int evaluations = 0;
  std::string reason;  // why the search stopped, in words
};

using SearchObjective = std::function<double(const std::vector<double>& x)>;

// The names SearchSettings::algorithm takes.
const std::vector<std::string>& search_algorithms();

// Minimises `objective` over [lower, upper] from `start`. Throws std::invalid_argument for
// bounds that are not increasing, a start outside them, or an unknown algorithm; an exception
// from the objective stops the search and is rethrown.
SearchResult minimise(const SearchObjective& objective, const std::vector<double>& lower,
                      const std::vector<double>& upper, const std::vector<double>& start,
                      const SearchSettings& settings);

}  // namespace partimix
