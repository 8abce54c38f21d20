#pragma once
// Rolling resistance models of DEM, chosen by name (docs/dem.md, "Rolling resistance"; Ai,
// Chen, Rotter and Ooi 2011): constant_torque (their model A, the seed's) and elastic_plastic
// (their model C), and none.
#include "core/registry.hpp"
#include "core/vec.hpp"

namespace partimix::dem {

struct RollingStep {
  double normal_force = 0.0;      // F_n [N]
  double normal_stiffness = 0.0;  // tangent k_n [N/m]
  double radius = 0.0;            // R* [m]
  double inertia = 0.0;           // I_r [kg m^2] (docs/dem.md)
  Vec3 normal = Vec3::UnitZ();
  Vec3 relative_angular_velocity = Vec3::Zero();  // omega_i - omega_j [rad/s]
  double coefficient = 0.0;                       // mu_r
  double dt = 0.0;
};

// omega_i - omega_j less its twisting part about the normal: the relative rolling velocity.
Vec3 rolling_velocity(const RollingStep& step);

class RollingResistance {
 public:
  virtual ~RollingResistance() = default;
  // The rolling torque on particle i; `spring` is the contact's rolling-spring torque (history
  // of the elastic-plastic model, unused by the others).
  virtual Vec3 torque(const RollingStep& step, Vec3& spring) const = 0;
};

struct RollingParameters {
  double viscous_damping = 0.3;  // eta_r of the elastic-plastic model
};

const Registry<RollingResistance, const RollingParameters&>& rolling_resistance_registry();

}  // namespace partimix::dem
