#include "analysis/shell_rupture.hpp"

namespace partimix::analysis {

bool ShellRupture::ruptured(std::span<const Vec3> position, std::span<const double> damage,
                            std::span<const ShellSurface> surface) {
  const std::size_t n = position.size();
  reached_.assign(n, 0);
  queue_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (surface[i] == ShellSurface::inner && damage[i] >= failed_) {
      reached_[i] = 1;
      queue_.push_back(i);
    }
  }
  const double link2 = link_ * link_;
  for (std::size_t q = 0; q < queue_.size(); ++q) {
    const std::size_t i = queue_[q];
    if (surface[i] == ShellSurface::outer)
      return true;
    for (std::size_t j = 0; j < n; ++j) {
      if (reached_[j] || damage[j] < failed_ || (position[j] - position[i]).squaredNorm() > link2)
        continue;
      reached_[j] = 1;
      queue_.push_back(j);
    }
  }
  return false;
}

}  // namespace partimix::analysis
