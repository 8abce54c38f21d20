#pragma once
// A 2D ring of four layers of particles (spacing 1, radii 20 to 23) for the tests of the shell
// analyses (analysis/shell_ring.hpp, analysis/shell_rupture.hpp), with cracks of damage.
#include <cmath>
#include <numbers>
#include <vector>

#include "core/vec.hpp"

namespace partimix::test_support {

struct FourLayerRing {
  static constexpr double kTwoPi = 2.0 * std::numbers::pi;

  // Lays the ring with a parting of arc `gap` on the inner layer at angle 0: the angles are
  // squeezed into [gap / 20, 2 pi), so the inner layer's ends are 1 + gap apart along it.
  void lay(double gap = 0.0) {
    position.clear();
    layer_of.clear();
    angle_of.clear();
    const double start = gap / 20.0;
    for (int layer = 0; layer < 4; ++layer) {
      const double radius = 20.0 + layer;
      const int count = static_cast<int>(std::round(kTwoPi * radius));
      for (int k = 0; k < count; ++k) {
        const double angle = start + (kTwoPi - start) * k / count;
        position.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
        layer_of.push_back(layer);
        angle_of.push_back(angle);
      }
    }
    damage.assign(position.size(), 0.0);
  }

  // Damages the particles within `half_width` radians of `at` on layers [0, layers).
  void crack(int layers, double half_width, double value = 1.0, double at = 0.0) {
    for (std::size_t i = 0; i < position.size(); ++i) {
      const double off = std::abs(std::remainder(angle_of[i] - at, kTwoPi));
      if (layer_of[i] < layers && off <= half_width)
        damage[i] = value;
    }
  }

  std::vector<Vec3> position;
  std::vector<int> layer_of;
  std::vector<double> angle_of;
  std::vector<double> damage;
};

}  // namespace partimix::test_support
