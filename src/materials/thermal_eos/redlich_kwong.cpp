#include "materials/thermal_eos/redlich_kwong.hpp"

#include <cmath>

namespace partimix::materials {

RedlichKwong::RedlichKwong(double molar_mass, double a, double b)
    : molar_mass_(molar_mass), a_(a), b_(b) {}

double RedlichKwong::pressure(double density, double temperature) const {
  const double v = molar_volume(density);
  return kMolarGasConstant * temperature / (v - b_) - a_ / (std::sqrt(temperature) * v * (v + b_));
}

double RedlichKwong::pressure_volume_derivative(double volume, double temperature) const {
  const double v = volume;
  const double excluded = v - b_;
  const double attraction = v * (v + b_);
  return -kMolarGasConstant * temperature / (excluded * excluded) +
         a_ * (2.0 * v + b_) / (std::sqrt(temperature) * attraction * attraction);
}

double RedlichKwong::pressure_density_derivative(double density, double temperature) const {
  const double v = molar_volume(density);
  return -pressure_volume_derivative(v, temperature) * v * v / molar_mass_;
}

double RedlichKwong::pressure_temperature_derivative(double density, double temperature) const {
  const double v = molar_volume(density);
  return kMolarGasConstant / (v - b_) +
         a_ / (2.0 * temperature * std::sqrt(temperature) * v * (v + b_));
}

}  // namespace partimix::materials
