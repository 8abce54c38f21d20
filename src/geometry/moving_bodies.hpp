#pragma once
// The bodies of a run (docs/motions.md): each wall of the case is one body, made of wall
// particles, with a prescribed motion. Every wall particle carries its body index (field
// "body", -1 for fluid) and its position at t = 0 (field "start_position"), so that moving a
// body is a closed-form placement at any time, with no drift from integrating velocities. Its
// angular velocity (field "angular_velocity") lets wall treatments extend the body's rigid
// velocity field into the fluid, and its acceleration (field "body_acceleration") enters the
// wall pressure (docs/sph.md, "Walls"). Its surface normal (field "surface_normal", set by the
// method that lays the particles before add_body, zero where it has none) turns with the body.
#include <algorithm>
#include <memory>
#include <vector>

#include "geometry/motion.hpp"
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix::geometry {

class MovingBodies {
 public:
  // Adds the "body", "start_position", "angular_velocity", "body_acceleration" and
  // "surface_normal" fields to `store` (body -1 for all particles).
  MovingBodies(ParticleStore& store, const Domain& domain);

  // Makes particles [first, store size) the particles of a new body with `motion`. Call after
  // appending them to the store, before any reordering.
  void add_body(std::size_t first, std::unique_ptr<Motion> motion);

  std::size_t count() const { return motions_.size(); }
  bool any_moving() const { return any_moving_; }
  const Motion& motion(std::size_t body) const { return *motions_[body]; }

  // Places every particle of a moving body where its motion puts it at `time`, with the rigid
  // velocity there, the body's angular velocity and the acceleration of the particle's material
  // point (a central difference of its rigid velocity over +-kAccelerationStep, exact to second
  // order for every motion, start-up ramps and planetary motion included; one-sided from t = 0
  // near the start, as motions begin at t = 0).
  void move_to(double time);

  static constexpr double kAccelerationStep = 1.0e-6;  // [s]
  static double difference_start(double time) { return std::max(time - kAccelerationStep, 0.0); }

 private:
  ParticleStore& store_;
  Domain domain_;
  std::vector<std::int32_t>& body_;
  std::vector<Vec3>& start_position_;
  std::vector<Vec3>& angular_velocity_;
  std::vector<Vec3>& acceleration_;
  std::vector<Vec3>& surface_normal_;
  std::vector<Vec3>& start_surface_normal_;
  std::vector<std::unique_ptr<Motion>> motions_;
  std::vector<bool> moving_;
  bool any_moving_ = false;
  std::vector<RigidPose> poses_;         // scratch: one per body, sized by add_body
  std::vector<RigidPose> poses_before_;  // at time - kAccelerationStep
  std::vector<RigidPose> poses_after_;   // at time + kAccelerationStep
};

}  // namespace partimix::geometry
