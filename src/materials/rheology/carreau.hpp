#pragma once
// Carreau-Yasuda fluid (Yasuda, Armstrong and Cohen 1981; Carreau 1972 for a = 2):
// eta = eta_inf + (eta0 - eta_inf) (1 + (lambda gamma_dot)^a)^((n-1)/a).
// n is the power-law index at high shear rate: eta - eta_inf ~ gamma_dot^(n-1); n < 1 thins,
// n > 1 thickens without bound.
#include "materials/rheology.hpp"

namespace partimix::materials {

class CarreauYasuda final : public Rheology {
 public:
  CarreauYasuda(double zero_shear_viscosity, double infinite_shear_viscosity, double time_constant,
                double flow_index, double yasuda_exponent);
  double apparent_viscosity(double shear_rate) const override;

 private:
  double eta0_;
  double eta_inf_;
  double lambda_;
  double n_;
  double a_;
};

}  // namespace partimix::materials
