#pragma once
// The walls as conditions on the grid's nodes (docs/mpm.md, "Walls: grid boundary
// conditions"): a node on or behind a wall's surface gets the wall's velocity (no_slip), loses
// the velocity into the wall (slip), or that and Coulomb friction (friction). The nodes of
// walls that do not move are found once; those of moving walls every step, among the nodes in
// use.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "geometry/motion.hpp"
#include "grid/cartesian_grid.hpp"
#include "mpm/config.hpp"

namespace partimix::mpm {

class GridBoundaries {
 public:
  GridBoundaries(const grid::CartesianGrid& grid, const std::vector<GridWall>& walls);

  // Applies the walls that do not move, then those that move (each kind in the order of the
  // walls), to the velocities of the `active` nodes at
  // `time`.
  void apply(double time, std::span<const std::size_t> active, std::vector<Vec3>& velocity) const;

 private:
  struct Contact {
    std::uint32_t wall = 0;
    Vec3 normal = Vec3::UnitZ();  // towards the material
  };
  bool contact(const GridWall& wall, const geometry::RigidPose* pose, const Vec3& x,
               Vec3& normal) const;
  void apply_node(std::size_t node, Vec3& velocity) const;

  const grid::CartesianGrid& grid_;
  std::vector<GridWall> walls_;
  std::vector<std::unique_ptr<geometry::Motion>> motions_;
  // Fixed walls: node n's contacts are contacts_[first_[n]] .. contacts_[first_[n + 1] - 1].
  std::vector<std::uint32_t> first_;
  std::vector<Contact> contacts_;
  mutable std::vector<geometry::RigidPose> poses_;  // of every wall at the time of apply()
};

// The velocity v relative to a wall moving with v_wall after the wall's condition, for a node
// behind it with normal n (docs/mpm.md, "Walls").
Vec3 wall_condition(const GridWall& wall, const Vec3& v, const Vec3& v_wall, const Vec3& n);

}  // namespace partimix::mpm
