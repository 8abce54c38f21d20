#pragma once
// Thermal equations of state p(rho, T) for the multi-material SPH of the gel-fuel droplet
// (docs/multi-material-sph.md, "Equations of state"; the seed's eqs. 4-5): the Tait liquid,
// the ideal gas and the Redlich-Kwong real gas. Models are chosen by name: tait, ideal_gas,
// redlich_kwong. Each model gives the pressure and its two partial derivatives, from which
// adiabatic_sound_speed() builds the sound speed of any model.
#include <string>

#include "core/registry.hpp"

namespace partimix::materials {

// The molar gas constant R [J/(mol K)] (exact since the 2019 SI redefinition).
inline constexpr double kMolarGasConstant = 8.314462618;

struct ThermalEosConfig {
  std::string model = "tait";
  double reference_density = 1000.0;  // tait: rho0 [kg/m^3]
  double sound_speed = 0.0;           // tait: c0 [m/s]
  double gamma = 7.0;                 // tait: exponent [-]
  double molar_mass = 0.0;            // ideal_gas, redlich_kwong: M [kg/mol]
  double a = 0.0;                     // redlich_kwong: attraction a [Pa m^6 K^0.5 mol^-2]
  double b = 0.0;                     // redlich_kwong: co-volume b [m^3/mol]
};

class ThermalEquationOfState {
 public:
  virtual ~ThermalEquationOfState() = default;
  // p [Pa] at density rho > 0 [kg/m^3] and temperature T > 0 [K].
  virtual double pressure(double density, double temperature) const = 0;
  // (dp/drho)_T [m^2/s^2].
  virtual double pressure_density_derivative(double density, double temperature) const = 0;
  // (dp/dT)_rho [Pa/K].
  virtual double pressure_temperature_derivative(double density, double temperature) const = 0;
};

// Models by name, built from the configuration; nullptr for an unknown name.
const Registry<ThermalEquationOfState, const ThermalEosConfig&>& thermal_eos_registry();

// The adiabatic (isentropic) sound speed [m/s] at (rho, T) for a specific heat at constant
// volume c_v [J/(kg K)]: c^2 = (dp/drho)_s = (dp/drho)_T + T (dp/dT)_rho^2 / (rho^2 c_v)
// (docs/multi-material-sph.md, "Equations of state").
double adiabatic_sound_speed(const ThermalEquationOfState& eos, double density, double temperature,
                             double specific_heat_cv);

}  // namespace partimix::materials
