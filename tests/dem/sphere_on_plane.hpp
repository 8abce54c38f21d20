#pragma once
// One sphere against the plane y = 0 (normal +y), moved by velocity Verlet with the contact laws
// of src/dem (docs/dem.md): the normal force, the tangential spring with its history and the
// rolling torque, at the contact point R - overlap/2 below the centre. For the oblique-impact and
// rolling tests, which need the laws alone, without the particle store.
#include <memory>

#include <Eigen/Geometry>

#include "core/vec.hpp"
#include "dem/normal_contact.hpp"
#include "dem/pair_properties.hpp"
#include "dem/rolling_resistance.hpp"
#include "dem/tangential_contact.hpp"

namespace partimix::dem::testing {

struct SphereOnPlane {
  const NormalContactLaw* normal_law = nullptr;
  const RollingResistance* rolling = nullptr;
  PairProperties pair;
  double radius = 0.0;
  double mass = 0.0;
  double friction = 0.0;          // mu_s
  double rolling_friction = 0.0;  // mu_r
  Vec3 gravity = Vec3::Zero();
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  Vec3 spring = Vec3::Zero();
  Vec3 rolling_spring = Vec3::Zero();
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  double normal_force = 0.0;  // of the last step, 0 out of contact

  double inertia() const { return 0.4 * mass * radius * radius; }

  void compute_loads(double dt) {
    force = mass * gravity;
    torque = Vec3::Zero();
    normal_force = 0.0;
    const Vec3 n = Vec3::UnitY();
    const double overlap = radius - position.y();
    if (overlap <= 0.0) {
      spring = Vec3::Zero();
      rolling_spring = Vec3::Zero();
      return;
    }
    const double lever = radius - 0.5 * overlap;
    const Vec3 contact_velocity = velocity - lever * angular_velocity.cross(n);
    const double u_n = contact_velocity.dot(n);
    const NormalResponse response = normal_law->respond(pair, overlap, u_n);
    normal_force = response.force;
    const TangentialStep tangential{response.tangential_stiffness,
                                    response.tangential_damping,
                                    normal_force,
                                    n,
                                    contact_velocity - u_n * n,
                                    friction,
                                    dt};
    const Vec3 f_t = tangential_force(tangential, spring);
    const RollingStep roll{normal_force,
                           response.normal_stiffness,
                           pair.radius,
                           inertia() + mass * radius * radius,
                           n,
                           angular_velocity,
                           rolling_friction,
                           dt};
    force += normal_force * n + f_t;
    torque += (-lever * n).cross(f_t) + rolling->torque(roll, rolling_spring);
  }

  void step(double dt) {
    velocity += 0.5 * dt / mass * force;
    angular_velocity += 0.5 * dt / inertia() * torque;
    position += dt * velocity;
    compute_loads(dt);
    velocity += 0.5 * dt / mass * force;
    angular_velocity += 0.5 * dt / inertia() * torque;
  }
};

}  // namespace partimix::dem::testing
