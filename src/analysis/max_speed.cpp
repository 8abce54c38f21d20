#include "analysis/max_speed.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::analysis {

void MaxSpeed::sample(const ParticleStore& particles, double /*time*/, std::span<double> values) {
  double max_speed2 = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i)) {
      max_speed2 = std::max(max_speed2, particles.velocity()[i].squaredNorm());
    }
  }
  values[0] = std::sqrt(max_speed2);
}

}  // namespace partimix::analysis
