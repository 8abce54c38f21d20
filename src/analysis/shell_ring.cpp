#include "analysis/shell_ring.hpp"

#include <cmath>
#include <numbers>

namespace partimix::analysis {
namespace {

// The angle from a to b, wrapped into (-pi, pi].
double turn(double a, double b) {
  return std::remainder(b - a, 2.0 * std::numbers::pi);
}

}  // namespace

bool ShellRing::closes(std::span<const Vec3> position, std::span<const double> damage,
                       const Vec3& centre) {
  const std::size_t n = position.size();
  angle_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    angle_[i] = std::atan2(position[i].y() - centre.y(), position[i].x() - centre.x());
  unwrapped_.assign(n, 0.0);
  reached_.assign(n, 0);
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (!reached_[seed] && damage[seed] < failed_ && closes_from(seed, position, damage))
      return true;
  }
  return false;
}

// Searches the component of `seed`: each particle reached takes the unwrapped angle of the one
// that reached it plus the turn between them; a join to a particle already reached whose
// unwrapped angles differ by about a whole turn closes a cycle round the centre.
bool ShellRing::closes_from(std::size_t seed, std::span<const Vec3> position,
                            std::span<const double> damage) {
  const double link2 = link_ * link_;
  queue_.assign(1, seed);
  reached_[seed] = 1;
  unwrapped_[seed] = angle_[seed];
  for (std::size_t q = 0; q < queue_.size(); ++q) {
    const std::size_t i = queue_[q];
    for (std::size_t j = 0; j < position.size(); ++j) {
      if (j == i || damage[j] >= failed_ || (position[j] - position[i]).squaredNorm() > link2)
        continue;
      const double along = unwrapped_[i] + turn(angle_[i], angle_[j]);
      if (!reached_[j]) {
        reached_[j] = 1;
        unwrapped_[j] = along;
        queue_.push_back(j);
      } else if (std::abs(along - unwrapped_[j]) > std::numbers::pi) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace partimix::analysis
