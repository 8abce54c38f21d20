#include "materials/granular/granular_stress.hpp"

#include <cmath>

#include "materials/granular/mu_i_return.hpp"

namespace partimix::materials {
namespace {

Mat3 deviator(const Mat3& t) {
  return t - (t.trace() / 3.0) * Mat3::Identity();
}

// tau = sqrt(s:s / 2).
double equivalent_shear_stress(const Mat3& s) {
  return std::sqrt(0.5 * s.squaredNorm());
}

}  // namespace

double granular_pressure(const GranularMaterial& material, double density) {
  if (!(density >= material.density))
    return 0.0;
  return material.bulk_modulus() * std::log(density / material.density);
}

void update_granular_stress(const GranularMaterial& material, const Mat3& velocity_gradient,
                            double dt, double density, GranularPoint& point) {
  const double pressure = granular_pressure(material, density);
  if (!(pressure > 0.0)) {  // disconnected: no contact, no stress
    point.stress.setZero();
    point.pressure = 0.0;
    point.inertial_number = 0.0;
    return;
  }
  const Mat3 rate = 0.5 * (velocity_gradient + velocity_gradient.transpose());
  const Mat3 spin = 0.5 * (velocity_gradient - velocity_gradient.transpose());
  const Mat3 s = point.stress + point.pressure * Mat3::Identity();
  const double shear_dt = material.shear_modulus() * dt;
  const Mat3 trial = s + dt * (spin * s - s * spin) + 2.0 * shear_dt * deviator(rate);
  const double tau_trial = equivalent_shear_stress(trial);
  const double flow = plastic_shear_rate(material, tau_trial, pressure, shear_dt);
  Mat3 deviatoric = trial;
  if (flow > 0.0)
    deviatoric *= (tau_trial - shear_dt * flow) / tau_trial;
  point.stress = deviatoric - pressure * Mat3::Identity();
  point.pressure = pressure;
  point.plastic_strain += dt * flow;
  point.inertial_number = material.inertial_number(flow, pressure);
}

}  // namespace partimix::materials
