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
#include "support/four_layer_ring.hpp"

namespace partimix::analysis {
namespace {

class RingOfFour : public ::testing::Test, protected test_support::FourLayerRing {
 protected:
  void SetUp() override { lay(); }

  bool closes(const Vec3& centre = Vec3::Zero()) {
    return ShellRing(1.5).closes(position, damage, centre);
  }
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
