// Shell rupture (docs/multi-material-sph.md, "The scheme", droplet measurements): a 2D ring of
// four layers of particles (spacing 1, radii 20 to 23) ruptures when a radial crack of fully
// damaged particles crosses all four layers, not when the crack stops a layer short, nor when a
// circumferential band of damage runs round the ring inside it, nor when damage is just short of
// full; cracks through the inner and outer layers far apart rupture it when a band joins them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/shell_rupture.hpp"
#include "support/four_layer_ring.hpp"

namespace partimix::analysis {
namespace {

class Ring : public ::testing::Test, protected test_support::FourLayerRing {
 protected:
  void SetUp() override {
    lay();
    for (const int layer : layer_of) {
      surface.push_back(layer == 0   ? ShellSurface::inner
                        : layer == 3 ? ShellSurface::outer
                                     : ShellSurface::none);
    }
  }

  bool ruptured() { return ShellRupture(1.5).ruptured(position, damage, surface); }

  std::vector<ShellSurface> surface;
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
