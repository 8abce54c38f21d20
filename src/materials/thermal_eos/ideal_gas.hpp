#pragma once
// The ideal gas (docs/multi-material-sph.md, "Equations of state"): p = rho R T / M with M the
// molar mass.
#include "materials/thermal_eos.hpp"

namespace partimix::materials {

class IdealGas final : public ThermalEquationOfState {
 public:
  explicit IdealGas(double molar_mass);
  double pressure(double density, double temperature) const override;
  // R T / M.
  double pressure_density_derivative(double density, double temperature) const override;
  // rho R / M.
  double pressure_temperature_derivative(double density, double temperature) const override;

 private:
  double specific_gas_constant_;  // R / M [J/(kg K)]
};

}  // namespace partimix::materials
