#include "analysis/droplet_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace partimix::analysis {

double equivalent_diameter(double volume, int dimensions) {
  if (dimensions == 2)
    return 2.0 * std::sqrt(volume / std::numbers::pi);
  return std::cbrt(6.0 * volume / std::numbers::pi);
}

double spacing_equivalent(double volume, int dimensions) {
  return dimensions == 2 ? std::sqrt(volume) : std::cbrt(volume);
}

double WeightedMean::value() const {
  return weight_ > 0.0 ? weighted_sum_ / weight_ : std::numeric_limits<double>::quiet_NaN();
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
