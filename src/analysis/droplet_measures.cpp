#include "analysis/droplet_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace partimix::analysis {

namespace {

// The half layer u = t / 2 of a spherical shell: (outer + u)^3 - (inner - u)^3 = 3 V / (4 pi),
// whose left side rises with u (its derivative 3 (outer + u)^2 + 3 (inner - u)^2 > 0), by
// Newton's method from the root of its part linear in u.
double spherical_half_layer(double inner, double outer, double shell_volume) {
  const double target = 3.0 * shell_volume / (4.0 * std::numbers::pi);
  const double cubed = outer * outer * outer - inner * inner * inner;
  double u = (target - cubed) / (3.0 * (outer * outer + inner * inner));
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double a = outer + u;
    const double b = inner - u;
    const double step = (a * a * a - b * b * b - target) / (3.0 * (a * a + b * b));
    u -= step;
    if (std::abs(step) <= 1e-15 * outer)
      break;
  }
  return u;
}

}  // namespace

double outline_diameter(double inner, double outer, double shell_volume, int dimensions) {
  const bool valid = std::isfinite(inner) && std::isfinite(outer) && std::isfinite(shell_volume) &&
                     inner > 0.0 && outer >= inner && shell_volume > 0.0;
  if (!valid)
    return std::numeric_limits<double>::quiet_NaN();
  // 2D: pi ((outer + t/2)^2 - (inner - t/2)^2) = pi (outer + inner) (outer - inner + t).
  const double half_layer =
      dimensions == 2
          ? 0.5 * (shell_volume / (std::numbers::pi * (outer + inner)) - (outer - inner))
          : spherical_half_layer(inner, outer, shell_volume);
  return 2.0 * (outer + half_layer);
}

double spacing_equivalent(double volume, int dimensions) {
  return dimensions == 2 ? std::sqrt(volume) : std::cbrt(volume);
}

double WeightedMean::value() const {
  return weight_ > 0.0 ? weighted_sum_ / weight_ : std::numeric_limits<double>::quiet_NaN();
}

double weighted_median(std::vector<std::pair<double, double>>& pairs) {
  const bool finite = std::ranges::all_of(pairs, [](const auto& pair) {
    return std::isfinite(pair.first) && std::isfinite(pair.second);
  });
  if (pairs.empty() || !finite)
    return std::numeric_limits<double>::quiet_NaN();
  std::ranges::sort(pairs);
  double total = 0.0;
  for (const auto& [value, weight] : pairs)
    total += weight;
  double reached = 0.0;
  for (const auto& [value, weight] : pairs) {
    reached += weight;
    if (reached >= 0.5 * total)
      return value;
  }
  return pairs.back().first;
}

void NearestSample::add(double time, double value) {
  const double distance = std::abs(time - target_);
  if (distance < distance_) {
    distance_ = distance;
    value_ = value;
  }
  reached_ = reached_ || time >= target_;
}

std::vector<ShellSurface> shell_surfaces(std::span<const double> distance,
                                         std::span<const double> spacing) {
  std::vector<ShellSurface> surface(distance.size(), ShellSurface::none);
  if (distance.empty())
    return surface;
  const auto [smallest, largest] = std::ranges::minmax_element(distance);
  for (std::size_t i = 0; i < distance.size(); ++i) {
    if (distance[i] <= *smallest + 0.5 * spacing[i])
      surface[i] = ShellSurface::inner;
    else if (distance[i] >= *largest - 0.5 * spacing[i])
      surface[i] = ShellSurface::outer;
  }
  return surface;
}

}  // namespace partimix::analysis
