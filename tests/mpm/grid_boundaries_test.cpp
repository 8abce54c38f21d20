// The walls as grid conditions (docs/mpm.md, "Walls: grid boundary conditions"): the three
// conditions on a node's velocity, and which nodes a wall holds: those on or behind its surface,
// a node on the surface included whatever the round-off in its coordinate (it decided, before,
// whether a silo's outlet edge was held, and two outlet widths gave the same rate).
#include "mpm/grid_boundaries.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "geometry/shape.hpp"

namespace partimix::mpm {
namespace {

TEST(WallCondition, NoSlipSlipAndCoulombFriction) {
  GridWall wall;
  const Vec3 n = Vec3::UnitY();
  const Vec3 v(3.0, -1.0, 0.0);
  const Vec3 wall_speed(0.5, 0.0, 0.0);
  wall.boundary = GridBoundary::no_slip;
  EXPECT_EQ(wall_condition(wall, v, wall_speed, n), wall_speed);
  wall.boundary = GridBoundary::slip;
  EXPECT_EQ(wall_condition(wall, v, wall_speed, n), Vec3(3.0, 0.0, 0.0));
  EXPECT_EQ(wall_condition(wall, Vec3(3.0, 1.0, 0.0), wall_speed, n), Vec3(3.0, 1.0, 0.0));
  wall.boundary = GridBoundary::friction;
  wall.friction = 0.5;  // |v_t| = 2.5 relative, |v_n| = 1: the slip loses 0.5
  EXPECT_LT((wall_condition(wall, v, wall_speed, n) - Vec3(2.5, 0.0, 0.0)).norm(), 1e-15);
  wall.friction = 5.0;  // friction stops the slip
  EXPECT_LT((wall_condition(wall, v, wall_speed, n) - wall_speed).norm(), 1e-15);
}

TEST(GridBoundaries, ANodeOnTheSurfaceIsHeldWhateverItsRoundOff) {
  Domain domain;
  domain.dimensions = 2;
  domain.lo = Vec3(-0.02, -0.02, 0.0);
  domain.hi = Vec3(0.1, 0.1, 0.0);
  const grid::CartesianGrid grid(domain, 0.01, 1e6);
  GridWall floor;
  floor.surface = geometry::Box(Vec3(0.02, -0.02, -1), Vec3(0.2, 0.0, 1)).make_surface(true, {});
  const GridBoundaries boundaries(grid, {floor});
  std::vector<std::size_t> active(grid.node_count());
  std::iota(active.begin(), active.end(), 0);
  std::vector<Vec3> velocity(grid.node_count(), Vec3(1.0, 1.0, 0.0));
  boundaries.apply(0.0, active, velocity);
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    const Vec3 x = grid.node_position(node);
    const bool on_or_behind =
        x.x() > 0.02 - 1e-12 && x.x() < 0.2 + 1e-12 && x.y() < 1e-12 && x.y() > -0.02 - 1e-12;
    const bool far = std::abs(x.y()) > 0.011 || x.x() < 0.009;
    if (on_or_behind) {
      EXPECT_EQ(velocity[node], Vec3::Zero()) << x.transpose();
    } else if (far) {
      EXPECT_EQ(velocity[node], Vec3(1.0, 1.0, 0.0)) << x.transpose();
    }
  }
  // The node at x = 0.02 is 0.019999999999999997 on this grid: it must be held.
  const std::size_t edge = grid.linear(6, 4, 0);
  EXPECT_LT(grid.node_position(edge).x(), 0.02);
  EXPECT_EQ(velocity[edge], Vec3::Zero());
}

}  // namespace
}  // namespace partimix::mpm
