// Shell rupture (docs/multi-material-sph.md, "The scheme", droplet measurements): a 2D ring of
// four layers of particles (spacing 1, radii 20 to 23) ruptures when a radial crack of fully
// damaged particles crosses all four layers, not when the crack stops a layer short, nor when a
// circumferential band of damage runs round the ring inside it, nor when damage is just short of
// full; cracks through the inner and outer layers far apart rupture it when a band joins them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/shell_rupture.hpp"

namespace partimix::analysis {
namespace {

class Ring : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int layer = 0; layer < 4; ++layer) {
      const double radius = 20.0 + layer;
      const int count = static_cast<int>(std::round(2.0 * std::numbers::pi * radius));
      for (int k = 0; k < count; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / count;
        position.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
        angle_of.push_back(angle);
        layer_of.push_back(layer);
        surface.push_back(layer == 0   ? ShellSurface::inner
                          : layer == 3 ? ShellSurface::outer
                                       : ShellSurface::none);
      }
    }
    damage.assign(position.size(), 0.0);
  }

  // Damages the particles within `half_width` radians of angle 0 on layers [0, layers).
  void crack(int layers, double half_width, double value = 1.0) {
    for (std::size_t i = 0; i < position.size(); ++i) {
      const double angle = std::min(angle_of[i], 2.0 * std::numbers::pi - angle_of[i]);
      if (layer_of[i] < layers && angle <= half_width)
        damage[i] = value;
    }
  }

  bool ruptured() { return ShellRupture(1.5).ruptured(position, damage, surface); }

  std::vector<Vec3> position;
  std::vector<double> angle_of;
  std::vector<int> layer_of;
  std::vector<ShellSurface> surface;
  std::vector<double> damage;
};

TEST_F(Ring, IntactRingHasNotRuptured) {
  EXPECT_FALSE(ruptured());
}

TEST_F(Ring, RadialCrackThroughAllLayersRuptures) {
  crack(4, 0.06);
  EXPECT_TRUE(ruptured());
}

TEST_F(Ring, CrackOneLayerShortDoesNotRupture) {
  crack(3, 0.06);
  EXPECT_FALSE(ruptured());
}

TEST_F(Ring, DamageJustShortOfFullDoesNotRupture) {
  crack(4, 0.06, 0.999);
  EXPECT_FALSE(ruptured());
}

TEST_F(Ring, CircumferentialBandDoesNotRupture) {
  for (std::size_t i = 0; i < position.size(); ++i) {
    if (layer_of[i] == 1 || layer_of[i] == 2)
      damage[i] = 1.0;
  }
  EXPECT_FALSE(ruptured());
}

// Cracks through the inner and the outer layer half a turn apart, joined by a damaged band
// round the middle layers: the path runs along the band.
TEST_F(Ring, OffsetCracksJoinedByABandRupture) {
  for (std::size_t i = 0; i < position.size(); ++i) {
    const bool middle = layer_of[i] == 1 || layer_of[i] == 2;
    const bool inner_crack = layer_of[i] == 0 && std::abs(angle_of[i] - 0.5) < 0.06;
    const bool outer_crack = layer_of[i] == 3 && std::abs(angle_of[i] - 3.6) < 0.06;
    if (middle || inner_crack || outer_crack)
      damage[i] = 1.0;
  }
  EXPECT_TRUE(ruptured());
}

}  // namespace
}  // namespace partimix::analysis
