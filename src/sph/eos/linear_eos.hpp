#pragma once
// Linear equation of state, the seed's eq. 3: p = c0^2 (rho - rho0).
#include "sph/equation_of_state.hpp"

namespace partimix::sph {

class LinearEos final : public EquationOfState {
 public:
  LinearEos(double reference_density, double sound_speed)
      : rho0_(reference_density), c2_(sound_speed * sound_speed) {}
  double pressure(double density) const override { return c2_ * (density - rho0_); }
  double density(double pressure) const override { return rho0_ + pressure / c2_; }

 private:
  double rho0_;
  double c2_;
};

}  // namespace partimix::sph
