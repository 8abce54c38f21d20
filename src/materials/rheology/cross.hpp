#pragma once
// Cross fluid (Cross 1965): eta = eta_inf + (eta0 - eta_inf) / (1 + (lambda gamma_dot)^n).
// n is Cross's rate constant: at high shear rate eta - eta_inf ~ gamma_dot^(-n), a power law of
// index 1 - n (some authors write the exponent as 1 - n instead). eta runs from eta0 at
// gamma_dot = 0 down to eta_inf as gamma_dot -> infinity.
#include "materials/rheology.hpp"

namespace partimix::materials {

class Cross final : public Rheology {
 public:
  Cross(double zero_shear_viscosity, double infinite_shear_viscosity, double time_constant,
        double flow_index);
  double apparent_viscosity(double shear_rate) const override;

 private:
  double eta0_;
  double eta_inf_;
  double lambda_;
  double n_;
};

}  // namespace partimix::materials
