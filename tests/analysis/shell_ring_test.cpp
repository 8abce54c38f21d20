// Shell ring (docs/multi-material-sph.md, "The scheme", droplet measurements): a 2D ring of four
// layers of particles (spacing 1, radii 20 to 23, joins within 1.5) closes round its centre until
// it opens: by a radial crack of fully damaged particles through all four layers, or by its
// particles parting at one angle by more than the join distance without any damage. A crack a
// layer short, damage just short of full, a parting narrower than the join distance or a centre
// off the ring leave the answer as they should.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/shell_ring.hpp"

namespace partimix::analysis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

class RingOfFour : public ::testing::Test {
 protected:
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

  void SetUp() override { lay(); }

  // Damages the particles within `half_width` radians of `at` on layers [0, layers).
  void crack(int layers, double half_width, double value = 1.0, double at = 0.0) {
    for (std::size_t i = 0; i < position.size(); ++i) {
      const double off = std::abs(std::remainder(angle_of[i] - at, kTwoPi));
      if (layer_of[i] < layers && off <= half_width)
        damage[i] = value;
    }
  }

  bool closes(const Vec3& centre = Vec3::Zero()) {
    return ShellRing(1.5).closes(position, damage, centre);
  }

  std::vector<Vec3> position;
  std::vector<int> layer_of;
  std::vector<double> angle_of;
  std::vector<double> damage;
};

TEST_F(RingOfFour, IntactRingCloses) {
  EXPECT_TRUE(closes());
}

TEST_F(RingOfFour, IntactRingClosesRoundAnOffCentrePointInside) {
  EXPECT_TRUE(closes(Vec3(12.0, -9.0, 0.0)));
}

TEST_F(RingOfFour, IntactRingDoesNotCloseRoundAPointOutside) {
  EXPECT_FALSE(closes(Vec3(40.0, 0.0, 0.0)));
}

TEST_F(RingOfFour, RadialCrackThroughAllLayersOpensIt) {
  crack(4, 0.06);
  EXPECT_FALSE(closes());
}

TEST_F(RingOfFour, CrackOneLayerShortLeavesItClosed) {
  crack(3, 0.06);
  EXPECT_TRUE(closes());
}

TEST_F(RingOfFour, DamageJustShortOfFullLeavesItClosed) {
  crack(4, 0.06, 0.999);
  EXPECT_TRUE(closes());
}

TEST_F(RingOfFour, TwoCracksLeaveTwoHalvesNeitherClosing) {
  crack(4, 0.06);
  crack(4, 0.06, 1.0, std::numbers::pi);
  EXPECT_FALSE(closes());
}

TEST_F(RingOfFour, PartingWiderThanTheJoinOpensItWithoutDamage) {
  lay(1.0);  // the inner layer's ends 2.0 apart, the outer's 2.15
  EXPECT_FALSE(closes());
}

TEST_F(RingOfFour, PartingNarrowerThanTheJoinLeavesItClosed) {
  lay(0.3);  // the inner layer's ends 1.3 apart
  EXPECT_TRUE(closes());
}

}  // namespace
}  // namespace partimix::analysis
