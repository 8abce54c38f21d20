#include "analysis/height_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace partimix::analysis {
namespace {

bool is_axis(int axis) {
  return axis >= 0 && axis < 3;
}

}  // namespace

HeightProfile::HeightProfile(const HeightLine& line) : line_(line), bins_per_length_(0.0) {
  if (!is_axis(line.axis) || !is_axis(line.vertical) || line.axis == line.vertical)
    throw std::invalid_argument("height_profile: axis and vertical must be two distinct axes");
  const double length = line.to - line.from;
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("height_profile: to must lie beyond from");
  if (line.bins < 1)
    throw std::invalid_argument("height_profile: bins must be at least 1");
  bins_per_length_ = line.bins / length;
  last_.assign(static_cast<std::size_t>(line.bins), std::numeric_limits<double>::quiet_NaN());
}

std::vector<Column> HeightProfile::columns() const {
  std::vector<Column> columns;
  for (int b = 0; b < line_.bins; ++b)
    columns.push_back({"height_" + std::to_string(b), "m"});
  return columns;
}

int HeightProfile::bin_of(double s) const {
  if (!(s >= line_.from && s <= line_.to))
    return -1;
  return std::min(line_.bins - 1, static_cast<int>((s - line_.from) * bins_per_length_));
}

void HeightProfile::sample(const ParticleStore& particles, double /*time*/,
                           std::span<double> values) {
  constexpr double kEmpty = -std::numeric_limits<double>::infinity();
  std::fill(last_.begin(), last_.end(), kEmpty);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const Vec3& x = particles.position()[i];
    const int bin = bin_of(x[line_.axis]);
    if (bin >= 0) {
      double& top = last_[static_cast<std::size_t>(bin)];
      top = std::max(top, x[line_.vertical]);
    }
  }
  for (std::size_t b = 0; b < last_.size(); ++b) {
    if (!std::isfinite(last_[b]))
      last_[b] = std::numeric_limits<double>::quiet_NaN();
    values[b] = last_[b];
  }
}

void HeightProfile::replay(double /*time*/, std::span<const double> values) {
  std::copy(values.begin(), values.end(), last_.begin());
}

void HeightProfile::add_figures(Figures& figures) const {
  double height_max = -std::numeric_limits<double>::infinity();
  int last_filled = -1;
  for (int b = 0; b < line_.bins; ++b) {
    const double height = last_[static_cast<std::size_t>(b)];
    if (std::isfinite(height)) {
      height_max = std::max(height_max, height);
      last_filled = b;
    }
  }
  if (last_filled < 0)
    return;
  figures.add("height_max", height_max, "m");
  figures.add("runout", line_.from + (line_.to - line_.from) * (last_filled + 1) / line_.bins, "m");
}

}  // namespace partimix::analysis
