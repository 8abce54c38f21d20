#include "analysis/angle_of_repose.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace partimix::analysis {

AngleOfRepose::AngleOfRepose(const ReposeSection& section)
    : section_(section),
      up_(Vec3::UnitY()),
      horizontal_(Vec3::UnitX()),
      last_(std::numeric_limits<double>::quiet_NaN()) {
  const double axis_norm = section.axis.norm();
  if (!(axis_norm > 0.0) || !std::isfinite(axis_norm))
    throw std::invalid_argument("angle_of_repose: the axis must be non-zero");
  const Vec3 axis = section.axis / axis_norm;
  const Vec3 down_normal = section.down - section.down.dot(axis) * axis;
  const double down_norm = down_normal.norm();
  if (!(down_norm > 1.0e-9 * section.down.norm()) || !std::isfinite(down_norm))
    throw std::invalid_argument("angle_of_repose: 'down' must not be parallel to the axis");
  up_ = -down_normal / down_norm;
  horizontal_ = up_.cross(axis);
  if (section.bins < 2)
    throw std::invalid_argument("angle_of_repose: bins must be at least 2");
  if (!(section.trim >= 0.0 && section.trim < 0.5))
    throw std::invalid_argument("angle_of_repose: trim must lie in [0, 0.5)");
  top_x_.assign(static_cast<std::size_t>(section.bins), 0.0);
  top_y_.assign(static_cast<std::size_t>(section.bins), 0.0);
  filled_.assign(static_cast<std::size_t>(section.bins), 0);
}

void AngleOfRepose::sample(const ParticleStore& particles, double /*time*/,
                           std::span<double> values) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  last_ = nan;
  values[0] = nan;
  // The bed's horizontal extent.
  double x_min = std::numeric_limits<double>::infinity();
  double x_max = -x_min;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const double x = (particles.position()[i] - section_.centre).dot(horizontal_);
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
  }
  const double width = x_max - x_min;
  if (!(width > 0.0) || !std::isfinite(width))
    return;
  // The highest particle of each bin.
  std::fill(filled_.begin(), filled_.end(), 0);
  const double bins_per_length = section_.bins / width;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const Vec3 r = particles.position()[i] - section_.centre;
    const double x = r.dot(horizontal_);
    const double y = r.dot(up_);
    if (!std::isfinite(x) || !std::isfinite(y))
      continue;
    const auto bin = static_cast<std::size_t>(
        std::clamp(static_cast<int>((x - x_min) * bins_per_length), 0, section_.bins - 1));
    if (!filled_[bin] || y > top_y_[bin]) {
      filled_[bin] = 1;
      top_x_[bin] = x;
      top_y_[bin] = y;
    }
  }
  // Least squares y = a + b x over the middle part of the surface.
  const double lo = x_min + section_.trim * width;
  const double hi = x_max - section_.trim * width;
  int n = 0;
  double sum_x = 0.0;
  double sum_y = 0.0;
  for (std::size_t b = 0; b < filled_.size(); ++b) {
    if (filled_[b] && top_x_[b] >= lo && top_x_[b] <= hi) {
      ++n;
      sum_x += top_x_[b];
      sum_y += top_y_[b];
    }
  }
  if (n < 2)
    return;
  const double mean_x = sum_x / n;
  const double mean_y = sum_y / n;
  double s_xx = 0.0;
  double s_xy = 0.0;
  for (std::size_t b = 0; b < filled_.size(); ++b) {
    if (filled_[b] && top_x_[b] >= lo && top_x_[b] <= hi) {
      const double dx = top_x_[b] - mean_x;
      s_xx += dx * dx;
      s_xy += dx * (top_y_[b] - mean_y);
    }
  }
  if (!(s_xx > 0.0))
    return;
  last_ = std::atan(std::abs(s_xy / s_xx)) * 180.0 / std::numbers::pi;
  values[0] = last_;
}

void AngleOfRepose::replay(double /*time*/, std::span<const double> values) {
  last_ = values[0];
}

void AngleOfRepose::add_figures(Figures& figures) const {
  if (std::isfinite(last_))
    figures.add("angle_of_repose_final", last_, "deg");
}

}  // namespace partimix::analysis
