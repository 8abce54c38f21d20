#pragma once
// Circular Couette flow about the z axis, as the Taylor-Couette tests measure it: the RMS
// deviation of the fluid's tangential velocity from r omega(r), and, for a Newtonian fluid with
// the inner cylinder turning and the outer at rest, the errors of the two cylinders' torques.
#include <cmath>
#include <numbers>

#include "analysis/body_load.hpp"
#include "particles/particle_store.hpp"

namespace partimix {

template <class AngularVelocity>
double tangential_rms_error(const ParticleStore& store, AngularVelocity&& omega) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    const Vec3& x = store.position()[i];
    const double r = std::hypot(x.x(), x.y());
    const Vec3 tangent(-x.y() / r, x.x() / r, 0.0);
    const double error = store.velocity()[i].dot(tangent) - r * omega(r);
    sum += error * error;
    ++count;
  }
  return std::sqrt(sum / count);
}

// Inner cylinder (body 0, radius `inner`) turning at `omega`, outer (body 1) at rest (Bird,
// Stewart and Lightfoot 2002, example 3.6-3): omega(r) = Omega (R2^2 / r^2 - 1) / (R2^2 / R1^2 -
// 1) and the torque 4 pi mu Omega R1^2 R2^2 / (R2^2 - R1^2) per unit length on each cylinder.
struct NewtonianTaylorCouette {
  double inner;
  double outer;
  double omega;
  double viscosity;
  double length;  // along the axis; 1 in 2D (torques per unit length)

  double angular_velocity(double r) const {
    return omega * (outer * outer / (r * r) - 1.0) / (outer * outer / (inner * inner) - 1.0);
  }
  double torque() const {
    return 4.0 * std::numbers::pi * viscosity * omega * inner * inner * outer * outer /
           (outer * outer - inner * inner) * length;
  }
};

// The tests' set-up: R1 = 5 mm turning at 2 rad/s, R2 = 10 mm, mu = 10 Pa s, per unit length.
inline constexpr NewtonianTaylorCouette kTaylorCouette{0.005, 0.01, 2.0, 10.0, 1.0};

struct TaylorCouetteErrors {
  double l2;     // of v_theta, relative to Omega R1
  double inner;  // torque on the inner cylinder, relative
  double outer;
};

// `store` with its bodies' loads up to date (Solver::update_body_forces).
inline TaylorCouetteErrors taylor_couette_errors(const ParticleStore& store,
                                                 const NewtonianTaylorCouette& flow) {
  const double l2 =
      tangential_rms_error(store, [&](double r) { return flow.angular_velocity(r); }) /
      (flow.omega * flow.inner);
  const auto torque = [&](int body) {
    return analysis::measure_body_load(store, body, Vec3::Zero(), Vec3::Zero()).torque_own.z();
  };
  return {l2, torque(0) / -flow.torque() - 1.0, torque(1) / flow.torque() - 1.0};
}

}  // namespace partimix
