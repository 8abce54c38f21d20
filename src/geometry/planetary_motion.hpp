#pragma once
// Planetary motion (docs/motions.md; the seed's eqs. 21-22): the body's own axis revolves at
// N_G rpm about the revolution (vessel) axis, and the body spins at N_R rpm about its own axis.
// N_R is the spin in the inertial frame, as in eq. 22 where a point moves with
// u_a = u_e + w_c x r_ca (u_e the revolution velocity of the own axis, w_c the spin).
#include "geometry/motion.hpp"
#include "geometry/start_up_ramp.hpp"

namespace partimix::geometry {

class PlanetaryMotion final : public Motion {
 public:
  // `own_axis_point`: a point of the body's own axis at t = 0; `centre`: a point of the
  // revolution axis; both axes are parallel to `axis`.
  PlanetaryMotion(const Vec3& own_axis_point, const Vec3& centre, const Vec3& axis, double spin_rpm,
                  double revolution_rpm, double ramp_time);
  RigidPose pose(double time) const override;

 private:
  Vec3 own_axis_point_;
  Vec3 centre_;
  Vec3 axis_;
  double spin_;        // omega_R [rad/s]
  double revolution_;  // omega_G [rad/s]
  StartUpRamp ramp_;
};

}  // namespace partimix::geometry
