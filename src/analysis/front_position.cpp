#include "analysis/front_position.hpp"

#include <algorithm>
#include <limits>

namespace partimix::analysis {

std::vector<Column> FrontPosition::columns() const {
  static const char* const axis_names[] = {"x", "y", "z"};
  return {{std::string("front_") + axis_names[axis_], "m"}};
}

void FrontPosition::sample(const ParticleStore& particles, double /*time*/,
                           std::span<double> values) {
  double front = std::numeric_limits<double>::lowest();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.is_material(i))
      front = std::max(front, particles.position()[i][axis_]);
  }
  values[0] = front;
}

}  // namespace partimix::analysis
