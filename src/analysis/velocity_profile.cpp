#include "analysis/velocity_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace partimix::analysis {

VelocityProfile::VelocityProfile(const ProfileLine& line)
    : line_(line), axis_(Vec3::UnitX()), length_(0.0), direction_(Vec3::UnitX()) {
  const Vec3 segment = line.end - line.start;
  length_ = segment.norm();
  if (!(length_ > 0.0) || !std::isfinite(length_))
    throw std::invalid_argument("velocity_profile: start and end must differ");
  if (line.bins < 1)
    throw std::invalid_argument("velocity_profile: bins must be at least 1");
  if (!(line.width > 0.0))
    throw std::invalid_argument("velocity_profile: width must be > 0");
  axis_ = segment / length_;
  if (!line.speed) {
    const double norm = line.direction.norm();
    if (!(norm > 0.0) || !std::isfinite(norm))
      throw std::invalid_argument("velocity_profile: the component direction must be non-zero");
    direction_ = line.direction / norm;
  }
  sums_.assign(static_cast<std::size_t>(line.bins), 0.0);
  counts_.assign(static_cast<std::size_t>(line.bins), 0);
  last_.assign(static_cast<std::size_t>(line.bins), std::numeric_limits<double>::quiet_NaN());
}

std::vector<Column> VelocityProfile::columns() const {
  std::vector<Column> columns;
  for (int b = 0; b < line_.bins; ++b)
    columns.push_back({"velocity_profile_" + std::to_string(b), "m/s"});
  return columns;
}

void VelocityProfile::sample(const ParticleStore& particles, double /*time*/,
                             std::span<double> values) {
  std::fill(sums_.begin(), sums_.end(), 0.0);
  std::fill(counts_.begin(), counts_.end(), 0);
  const double half_width_squared = 0.25 * line_.width * line_.width;
  const double bins_per_length = line_.bins / length_;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const Vec3 d = particles.position()[i] - line_.start;
    const double s = d.dot(axis_);
    if (!(s >= 0.0 && s <= length_))
      continue;
    if ((d - s * axis_).squaredNorm() > half_width_squared)
      continue;
    const int bin = std::min(line_.bins - 1, static_cast<int>(s * bins_per_length));
    const Vec3& v = particles.velocity()[i];
    sums_[static_cast<std::size_t>(bin)] += line_.speed ? v.norm() : v.dot(direction_);
    ++counts_[static_cast<std::size_t>(bin)];
  }
  for (std::size_t b = 0; b < sums_.size(); ++b) {
    values[b] = counts_[b] > 0 ? sums_[b] / static_cast<double>(counts_[b])
                               : std::numeric_limits<double>::quiet_NaN();
    last_[b] = values[b];
  }
}

void VelocityProfile::replay(double /*time*/, std::span<const double> values) {
  std::copy(values.begin(), values.end(), last_.begin());
}

void VelocityProfile::add_figures(Figures& figures) const {
  for (std::size_t b = 0; b < last_.size(); ++b) {
    if (std::isfinite(last_[b]))
      figures.add("velocity_profile_" + std::to_string(b) + "_final", last_[b], "m/s");
  }
}

}  // namespace partimix::analysis
