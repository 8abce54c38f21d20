#pragma once
// The load of the surrounding material on one body (docs/power.md; the seed's eq. 23): the sum
// of the forces on its particles (field "body_force"), their moments about the body's own axis
// and about the vessel axis (with the particles' couples, field "body_couple"), and the
// mechanical power the body gives the material.
#include "core/vec.hpp"
#include "geometry/motion.hpp"
#include "particles/particle_store.hpp"

namespace partimix::analysis {

struct BodyLoad {
  Vec3 force = Vec3::Zero();          // F = sum_j f_j [N]
  Vec3 torque_own = Vec3::Zero();     // sum_j (x_j - o) x f_j + c_j, o on the own axis [N m]
  Vec3 torque_vessel = Vec3::Zero();  // sum_j (x_j - c) x f_j + c_j, c on the vessel axis [N m]
};

// Sums over the particles whose field "body" equals `body`.
// Throws RunError when the store has no "body", "body_force" or "body_couple" field.
BodyLoad measure_body_load(const ParticleStore& particles, int body, const Vec3& own_axis_point,
                           const Vec3& vessel_axis_point);

// The mechanical power the body gives the material [W]: -sum_j (f_j . u_j + omega . c_j) with
// the rigid velocities u_j = v_o + omega x (x_j - o), that is -(F . v_o + omega . Gamma_o) for
// `load` measured about the point o = `own_axis_point` of the body in `pose`.
inline double power_given(const BodyLoad& load, const geometry::RigidPose& pose,
                          const Vec3& own_axis_point) {
  return -(load.force.dot(pose.velocity_at(own_axis_point)) +
           pose.angular_velocity.dot(load.torque_own));
}

}  // namespace partimix::analysis
