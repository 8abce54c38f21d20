#include "mpm/grid_boundaries.hpp"

#include <algorithm>
#include <stdexcept>

namespace partimix::mpm {

Vec3 wall_condition(const GridWall& wall, const Vec3& v, const Vec3& v_wall, const Vec3& n) {
  const Vec3 relative = v - v_wall;
  if (wall.boundary == GridBoundary::no_slip)
    return v_wall;
  const double normal = relative.dot(n);
  if (normal >= 0.0)  // leaving the wall: untouched
    return v;
  const Vec3 tangential = relative - normal * n;
  if (wall.boundary == GridBoundary::slip)
    return v_wall + tangential;
  const double speed = tangential.norm();
  const double keep = speed > 0.0 ? std::max(0.0, 1.0 - wall.friction * (-normal) / speed) : 0.0;
  return v_wall + keep * tangential;
}

GridBoundaries::GridBoundaries(const grid::CartesianGrid& grid, const std::vector<GridWall>& walls)
    : grid_(grid), walls_(walls) {
  for (const GridWall& wall : walls_) {
    motions_.push_back(geometry::motion_registry().create(wall.motion.type, wall.motion));
    if (!motions_.back())
      throw std::logic_error("unknown motion type " + wall.motion.type);
  }
  poses_.resize(walls_.size());
  first_.assign(grid.node_count() + 1, 0);
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    first_[node] = static_cast<std::uint32_t>(contacts_.size());
    for (std::uint32_t w = 0; w < walls_.size(); ++w) {
      Vec3 normal;
      if (!motions_[w]->moves() && contact(walls_[w], nullptr, grid.node_position(node), normal))
        contacts_.push_back({w, normal});
    }
  }
  first_[grid.node_count()] = static_cast<std::uint32_t>(contacts_.size());
}

// Whether x is on or behind the wall's surface (gap <= 0, to round-off), and the normal there; a
// moving wall is asked in its own frame at t = 0 through `pose`.
bool GridBoundaries::contact(const GridWall& wall, const geometry::RigidPose* pose, const Vec3& x,
                             Vec3& normal) const {
  const double reach = 3.0 * grid_.cell_size();
  Vec3 local = x;
  if (pose != nullptr)
    local = pose->rotation.transpose() * (x - pose->origin) + pose->start_origin;
  geometry::SurfacePoint point;
  // A node on the surface is behind it: round-off in the node's coordinate must not decide.
  if (!wall.surface->nearest(local, reach, point) || point.gap > 1e-9 * grid_.cell_size())
    return false;
  normal = pose != nullptr ? Vec3(pose->rotation * point.normal) : point.normal;
  return true;
}

void GridBoundaries::apply(double time, std::span<const std::size_t> active,
                           std::vector<Vec3>& velocity) const {
  for (std::size_t w = 0; w < motions_.size(); ++w)
    poses_[w] = motions_[w]->pose(time);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(active.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < count; ++k)
    apply_node(active[k], velocity[active[k]]);
}

void GridBoundaries::apply_node(std::size_t node, Vec3& v) const {
  for (std::uint32_t c = first_[node]; c < first_[node + 1]; ++c) {
    const GridWall& wall = walls_[contacts_[c].wall];
    v = wall_condition(wall, v, Vec3::Zero(), contacts_[c].normal);
  }
  const Vec3 x = grid_.node_position(node);
  for (std::uint32_t w = 0; w < walls_.size(); ++w) {
    Vec3 normal;
    if (motions_[w]->moves() && contact(walls_[w], &poses_[w], x, normal))
      v = wall_condition(walls_[w], v, poses_[w].velocity_at(x), normal);
  }
}

}  // namespace partimix::mpm
