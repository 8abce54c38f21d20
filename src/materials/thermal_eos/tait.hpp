#pragma once
// The Tait equation of the weakly compressible liquid (Monaghan 1994; the seed's eq. 5;
// docs/multi-material-sph.md, "Equations of state"): p = p0 [(rho/rho0)^gamma - 1] with
// p0 = rho0 c0^2 / gamma, so that (dp/drho) = c0^2 at rho0. Temperature is ignored.
#include "materials/thermal_eos.hpp"

namespace partimix::materials {

class Tait final : public ThermalEquationOfState {
 public:
  Tait(double reference_density, double sound_speed, double gamma);
  double pressure(double density, double temperature) const override;
  // c0^2 (rho/rho0)^(gamma - 1).
  double pressure_density_derivative(double density, double temperature) const override;
  // 0: the liquid's pressure does not depend on temperature.
  double pressure_temperature_derivative(double density, double temperature) const override;
  // The inverse, rho(p); pressures below -p0 (which no density reaches) give 0.
  double density(double pressure) const;

 private:
  double reference_pressure() const;  // p0 = rho0 c0^2 / gamma

  double reference_density_;
  double sound_speed_squared_;
  double gamma_;
};

}  // namespace partimix::materials
