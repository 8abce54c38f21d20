#include "materials/thermal_eos/ideal_gas.hpp"

namespace partimix::materials {

IdealGas::IdealGas(double molar_mass) : specific_gas_constant_(kMolarGasConstant / molar_mass) {}

double IdealGas::pressure(double density, double temperature) const {
  return density * specific_gas_constant_ * temperature;
}

double IdealGas::pressure_density_derivative(double /*density*/, double temperature) const {
  return specific_gas_constant_ * temperature;
}

double IdealGas::pressure_temperature_derivative(double density, double /*temperature*/) const {
  return density * specific_gas_constant_;
}

}  // namespace partimix::materials
