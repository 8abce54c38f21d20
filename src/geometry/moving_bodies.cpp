#include "geometry/moving_bodies.hpp"

#include <algorithm>

namespace partimix::geometry {

MovingBodies::MovingBodies(ParticleStore& store, const Domain& domain)
    : store_(store),
      domain_(domain),
      body_(store.add_integer("body", "").values),
      start_position_(store.add_vector("start_position", "m", false).values),
      angular_velocity_(store.add_vector("angular_velocity", "rad/s", false).values),
      acceleration_(store.add_vector("body_acceleration", "m/s^2", false).values),
      surface_normal_(store.add_vector("surface_normal", "", false).values),
      start_surface_normal_(store.add_vector("start_surface_normal", "", false).values) {
  std::fill(body_.begin(), body_.end(), -1);
}

void MovingBodies::add_body(std::size_t first, std::unique_ptr<Motion> motion) {
  const auto index = static_cast<std::int32_t>(motions_.size());
  for (std::size_t i = first; i < store_.size(); ++i) {
    body_[i] = index;
    start_position_[i] = store_.position()[i];
    start_surface_normal_[i] = surface_normal_[i];
  }
  const bool moving = motion->moves();
  moving_.push_back(moving);
  any_moving_ = any_moving_ || moving;
  motions_.push_back(std::move(motion));
  poses_.resize(motions_.size());
  poses_before_.resize(motions_.size());
  poses_after_.resize(motions_.size());
}

void MovingBodies::move_to(double time) {
  if (!any_moving_)
    return;
  for (std::size_t b = 0; b < motions_.size(); ++b) {
    if (moving_[b]) {
      poses_[b] = motions_[b]->pose(time);
      poses_before_[b] = motions_[b]->pose(difference_start(time));
      poses_after_[b] = motions_[b]->pose(difference_start(time) + 2.0 * kAccelerationStep);
    }
  }
  auto& position = store_.position();
  auto& velocity = store_.velocity();
  const auto n = static_cast<std::ptrdiff_t>(store_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    if (body_[i] < 0 || !moving_[static_cast<std::size_t>(body_[i])])
      continue;
    const auto b = static_cast<std::size_t>(body_[i]);
    const Vec3& start = start_position_[i];
    position[i] = poses_[b].place(start);
    velocity[i] = poses_[b].velocity_at(position[i]);
    angular_velocity_[i] = poses_[b].angular_velocity;
    surface_normal_[i] = poses_[b].rotation * start_surface_normal_[i];
    const Vec3 before = poses_before_[b].velocity_at(poses_before_[b].place(start));
    const Vec3 after = poses_after_[b].velocity_at(poses_after_[b].place(start));
    acceleration_[i] = (after - before) / (2.0 * kAccelerationStep);
    domain_.wrap(position[i]);
  }
}

}  // namespace partimix::geometry
