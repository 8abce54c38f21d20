#pragma once
// Tait equation of state (Monaghan 1994, eq. 3.4): p = B ((rho/rho0)^gamma - 1),
// B = c0^2 rho0 / gamma, so that dp/drho = c0^2 at rho0; pressures below -B (which no density
// reaches) map to the smallest density, 0.
#include "materials/thermal_eos/tait.hpp"
#include "sph/equation_of_state.hpp"

namespace partimix::sph {

// The shared law (materials/thermal_eos/tait.hpp) at the one temperature SPH's single fluid has.
class TaitEos final : public EquationOfState {
 public:
  TaitEos(double reference_density, double sound_speed, double gamma)
      : law_(reference_density, sound_speed, gamma) {}
  double pressure(double density) const override { return law_.pressure(density, 0.0); }
  double density(double pressure) const override { return law_.density(pressure); }

 private:
  materials::Tait law_;
};

}  // namespace partimix::sph
