#include "materials/thermal_eos.hpp"

#include <cmath>
#include <memory>

#include "materials/thermal_eos/ideal_gas.hpp"
#include "materials/thermal_eos/redlich_kwong.hpp"
#include "materials/thermal_eos/tait.hpp"

namespace partimix::materials {

const Registry<ThermalEquationOfState, const ThermalEosConfig&>& thermal_eos_registry() {
  static const Registry<ThermalEquationOfState, const ThermalEosConfig&> registry = [] {
    Registry<ThermalEquationOfState, const ThermalEosConfig&> r;
    r.add("tait", [](const ThermalEosConfig& c) {
      return std::make_unique<Tait>(c.reference_density, c.sound_speed, c.gamma);
    });
    r.add("ideal_gas",
          [](const ThermalEosConfig& c) { return std::make_unique<IdealGas>(c.molar_mass); });
    r.add("redlich_kwong", [](const ThermalEosConfig& c) {
      return std::make_unique<RedlichKwong>(c.molar_mass, c.a, c.b);
    });
    return r;
  }();
  return registry;
}

// From p(rho, s) = p(rho, T(rho, s)) and (dT/drho)_s = T (dp/dT)_rho / (rho^2 c_v), a Maxwell
// relation with de = c_v dT + (p - T (dp/dT)_rho) / rho^2 drho.
double adiabatic_sound_speed(const ThermalEquationOfState& eos, double density, double temperature,
                             double specific_heat_cv) {
  const double thermal = eos.pressure_temperature_derivative(density, temperature);
  return std::sqrt(eos.pressure_density_derivative(density, temperature) +
                   temperature * thermal * thermal / (density * density * specific_heat_cv));
}

}  // namespace partimix::materials
