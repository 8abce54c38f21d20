#include "materials/thermal_eos/tait.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::materials {

Tait::Tait(double reference_density, double sound_speed, double gamma)
    : reference_density_(reference_density),
      sound_speed_squared_(sound_speed * sound_speed),
      gamma_(gamma) {}

double Tait::reference_pressure() const {
  return reference_density_ * sound_speed_squared_ / gamma_;
}

double Tait::pressure(double density, double /*temperature*/) const {
  return reference_pressure() * (std::pow(density / reference_density_, gamma_) - 1.0);
}

double Tait::density(double pressure) const {
  return reference_density_ *
         std::pow(std::max(1.0 + pressure / reference_pressure(), 0.0), 1.0 / gamma_);
}

double Tait::pressure_density_derivative(double density, double /*temperature*/) const {
  return sound_speed_squared_ * std::pow(density / reference_density_, gamma_ - 1.0);
}

double Tait::pressure_temperature_derivative(double /*density*/, double /*temperature*/) const {
  return 0.0;
}

}  // namespace partimix::materials
