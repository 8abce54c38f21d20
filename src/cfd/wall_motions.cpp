#include "cfd/wall_motions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace partimix::cfd {
namespace {

// Fractions of a turn, irrational to each other, so that no rotational symmetry of a shape
// (a blade set, a square) maps it onto itself at every one of them.
constexpr std::array<double, 5> kTurnFractions{0.1234, 0.2718, 0.4142, 0.5772, 0.7071};

}  // namespace

WallMotions::WallMotions(std::vector<std::shared_ptr<const geometry::Motion>> motions,
                         FluidFrame frame)
    : motions_(std::move(motions)), frame_(std::move(frame)), wall_poses_(motions_.size()) {
  any_moving_ = std::any_of(motions_.begin(), motions_.end(), [&](const auto& m) {
    return !frame_.follows(*m) && (frame_.rotating() || m->moves());
  });
}

void WallMotions::set_time(double time) {
  frame_pose_ = frame_.pose(time);
  for (std::size_t w = 0; w < motions_.size(); ++w)
    wall_poses_[w] = motions_[w]->pose(time);
}

Vec3 WallMotions::velocity(std::size_t wall, const Vec3& x) const {
  const Vec3 lab = frame_pose_.place(x);
  const Vec3 relative = wall_poses_[wall].velocity_at(lab) - frame_pose_.velocity_at(lab);
  return frame_pose_.rotation.transpose() * relative;
}

int WallMotions::first_not_in_place(
    const grid::StaggeredGrid& grid,
    std::span<const std::shared_ptr<const geometry::Surface>> surfaces,
    const InPlaceSamples& samples) const {
  for (std::size_t w = 0; w < surfaces.size(); ++w)
    if (!in_place(grid, w, *surfaces[w], samples))
      return static_cast<int>(w);
  return -1;
}

// A frame point x is, at time t, at the wall's body point start + R_wᵀ (place(x) - origin_w).
// A wall at rest in the lab seen from the lab, or the frame's own body, is in place without a
// look; otherwise the cells within 2 h of its surface at t = 0 are found once and looked at again
// at each sampled time.
bool WallMotions::in_place(const grid::StaggeredGrid& grid, std::size_t wall,
                           const geometry::Surface& surface, const InPlaceSamples& samples) const {
  const geometry::Motion& motion = *motions_[wall];
  if ((!frame_.rotating() && !motion.moves()) || frame_.follows(motion))
    return true;
  double h = 0.0;
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    h = std::max(h, grid.spacing(axis));
  const double reach = 2.0 * h;
  std::vector<std::pair<Vec3, double>> near;  // cell centre, gap at t = 0
  grid.for_each_cell([&](const std::array<int, 3>& c, std::size_t) {
    const Vec3 x = grid.cell_centre(c[0], c[1], c[2]);
    geometry::SurfacePoint point;
    if (surface.nearest(x, reach, point) && std::abs(point.gap) <= reach)
      near.emplace_back(x, point.gap);
  });
  for (const double fraction : kTurnFractions) {
    const double time = samples.start + fraction * samples.period;
    const geometry::RigidPose frame = frame_.pose(time);
    const geometry::RigidPose body = motion.pose(time);
    for (const auto& [x, gap] : near) {
      const Vec3 seen =
          body.start_origin + body.rotation.transpose() * (frame.place(x) - body.origin);
      geometry::SurfacePoint now;
      // Looked up with twice the reach: a centre found at the reach's edge at t = 0 may lie a
      // round-off beyond it once turned (a centre 0.1 m from the axis of a drum of 0.12 m on
      // cells of 0.01 m was refused so).
      if (!surface.nearest(seen, 2.0 * reach, now) || std::abs(now.gap - gap) > 1e-6 * h)
        return false;
    }
  }
  return true;
}

}  // namespace partimix::cfd
