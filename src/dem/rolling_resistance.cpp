#include "dem/rolling_resistance.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace partimix::dem {

Vec3 rolling_velocity(const RollingStep& step) {
  const Vec3& w = step.relative_angular_velocity;
  return w - w.dot(step.normal) * step.normal;
}

namespace {

class NoRollingResistance final : public RollingResistance {
 public:
  Vec3 torque(const RollingStep&, Vec3&) const override { return Vec3::Zero(); }
};

// Model A: M_r = -mu_r |F_n| R* w/|w|, no larger than the torque I_r |w| / dt that stops the
// relative rolling in one step, so that a sphere at rest does not rock back and forth.
class ConstantTorque final : public RollingResistance {
 public:
  Vec3 torque(const RollingStep& step, Vec3&) const override {
    const Vec3 w = rolling_velocity(step);
    const double speed = w.norm();
    if (speed == 0.0)
      return Vec3::Zero();
    const double limit = step.coefficient * std::abs(step.normal_force) * step.radius;
    return -std::min(limit, step.inertia * speed / step.dt) / speed * w;
  }
};

// Model C: a spring k_r = 2.25 k_n mu_r^2 R*^2 capped at mu_r |F_n| R*, with a dashpot
// 2 eta_r sqrt(I_r k_r) while the spring is below its cap.
class ElasticPlastic final : public RollingResistance {
 public:
  explicit ElasticPlastic(double viscous_damping) : viscous_damping_(viscous_damping) {}

  Vec3 torque(const RollingStep& step, Vec3& spring) const override {
    const Vec3 w = rolling_velocity(step);
    const double stiffness =
        2.25 * step.normal_stiffness * std::pow(step.coefficient * step.radius, 2);
    spring -= spring.dot(step.normal) * step.normal;
    spring -= stiffness * step.dt * w;
    const double cap = step.coefficient * std::abs(step.normal_force) * step.radius;
    const double size = spring.norm();
    if (size >= cap) {
      spring *= size > 0.0 ? cap / size : 0.0;
      return spring;
    }
    const double damping = 2.0 * viscous_damping_ * std::sqrt(step.inertia * stiffness);
    return spring - damping * w;
  }

 private:
  double viscous_damping_;
};

}  // namespace

const Registry<RollingResistance, const RollingParameters&>& rolling_resistance_registry() {
  static const Registry<RollingResistance, const RollingParameters&> registry = [] {
    Registry<RollingResistance, const RollingParameters&> r;
    r.add("none", [](const RollingParameters&) { return std::make_unique<NoRollingResistance>(); });
    r.add("constant_torque",
          [](const RollingParameters&) { return std::make_unique<ConstantTorque>(); });
    r.add("elastic_plastic", [](const RollingParameters& p) {
      return std::make_unique<ElasticPlastic>(p.viscous_damping);
    });
    return r;
  }();
  return registry;
}

}  // namespace partimix::dem
