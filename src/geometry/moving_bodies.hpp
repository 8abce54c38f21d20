#pragma once
// The bodies of a run (docs/motions.md): each wall of the case is one body, made of wall
// particles, with a prescribed motion. Every wall particle carries its body index (field
// "body", -1 for fluid) and its position at t = 0 (field "start_position"), so that moving a
// body is a closed-form placement at any time, with no drift from integrating velocities. Its
// angular velocity (field "angular_velocity") lets wall treatments extend the body's rigid
// velocity field into the fluid (docs/sph.md, "Walls").
#include <memory>
#include <vector>

#include "geometry/motion.hpp"
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix::geometry {

class MovingBodies {
 public:
  // Adds the "body", "start_position" and "angular_velocity" fields to `store` (body -1 for all
  // particles).
  MovingBodies(ParticleStore& store, const Domain& domain);

  // Makes particles [first, store size) the particles of a new body with `motion`. Call after
  // appending them to the store, before any reordering.
  void add_body(std::size_t first, std::unique_ptr<Motion> motion);

  std::size_t count() const { return motions_.size(); }
  bool any_moving() const { return any_moving_; }
  const Motion& motion(std::size_t body) const { return *motions_[body]; }

  // Places every particle of a moving body where its motion puts it at `time`, with the rigid
  // velocity there and the body's angular velocity.
  void move_to(double time);

 private:
  ParticleStore& store_;
  Domain domain_;
  std::vector<std::int32_t>& body_;
  std::vector<Vec3>& start_position_;
  std::vector<Vec3>& angular_velocity_;
  std::vector<std::unique_ptr<Motion>> motions_;
  std::vector<bool> moving_;
  bool any_moving_ = false;
  std::vector<RigidPose> poses_;  // scratch: one per body, sized by add_body
};

}  // namespace partimix::geometry
