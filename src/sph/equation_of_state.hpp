#pragma once
// Equations of state closing weakly-compressible SPH (docs/sph.md, "Equation of state").
// Each maps density to pressure and back (the inverse gives wall densities from extrapolated
// wall pressures and hydrostatic initial densities).
#include "core/registry.hpp"

namespace partimix::sph {

class EquationOfState {
 public:
  virtual ~EquationOfState() = default;
  virtual double pressure(double density) const = 0;
  virtual double density(double pressure) const = 0;
};

struct EosParameters {
  double reference_density;  // rho0 [kg/m^3]
  double sound_speed;        // c0 [m/s]
  double gamma;              // Tait exponent
};

// Equations of state by name: linear (the seed's eq. 3), tait (Monaghan 1994, eq. 3.4).
const Registry<EquationOfState, const EosParameters&>& equation_of_state_registry();

}  // namespace partimix::sph
