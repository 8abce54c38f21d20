#pragma once
// Tait equation of state (Monaghan 1994, eq. 3.4): p = B ((rho/rho0)^gamma - 1),
// B = c0^2 rho0 / gamma, so that dp/drho = c0^2 at rho0.
#include <algorithm>
#include <cmath>

#include "sph/equation_of_state.hpp"

namespace partimix::sph {

class TaitEos final : public EquationOfState {
 public:
  TaitEos(double reference_density, double sound_speed, double gamma)
      : rho0_(reference_density),
        gamma_(gamma),
        b_(sound_speed * sound_speed * reference_density / gamma) {}
  double pressure(double density) const override {
    return b_ * (std::pow(density / rho0_, gamma_) - 1.0);
  }
  // Pressures below -B (which no density reaches) map to the smallest density, 0.
  double density(double pressure) const override {
    return rho0_ * std::pow(std::max(1.0 + pressure / b_, 0.0), 1.0 / gamma_);
  }

 private:
  double rho0_;
  double gamma_;
  double b_;
};

}  // namespace partimix::sph
