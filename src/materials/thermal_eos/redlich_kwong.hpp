#pragma once
// The Redlich-Kwong real gas (Redlich & Kwong 1949; the seed's eq. 4;
// docs/multi-material-sph.md, "Equations of state"):
//   p = R T / (V - b) - a / (sqrt(T) V (V + b)),  V = M / rho the molar volume,
// with a [Pa m^6 K^0.5 mol^-2] the attraction and b [m^3/mol] the co-volume. It tends to the
// ideal gas as V / b -> infinity; valid for V > b.
#include "materials/thermal_eos.hpp"

namespace partimix::materials {

class RedlichKwong final : public ThermalEquationOfState {
 public:
  RedlichKwong(double molar_mass, double a, double b);
  double pressure(double density, double temperature) const override;
  // -(dp/dV)_T V^2 / M, as dV/drho = -V^2 / M.
  double pressure_density_derivative(double density, double temperature) const override;
  // R / (V - b) + a / (2 T^1.5 V (V + b)).
  double pressure_temperature_derivative(double density, double temperature) const override;
  // (dp/dV)_T = -R T / (V - b)^2 + a (2 V + b) / (sqrt(T) V^2 (V + b)^2) [Pa mol/m^3].
  double pressure_volume_derivative(double volume, double temperature) const;

 private:
  double molar_volume(double density) const { return molar_mass_ / density; }

  double molar_mass_;
  double a_;
  double b_;
};

}  // namespace partimix::materials
