#pragma once
// Power-law (Ostwald-de Waele) fluid: tau = K gamma_dot^n, so eta = K gamma_dot^(n-1)
// (docs/rheology.md, "Power law"). Shear-thinning for n < 1 (eta -> infinity as
// gamma_dot -> 0), shear-thickening for n > 1 (eta -> infinity as gamma_dot -> infinity).
#include "materials/rheology.hpp"

namespace partimix::materials {

class PowerLaw final : public Rheology {
 public:
  PowerLaw(double consistency, double flow_index);
  // +infinity at gamma_dot = 0 when n < 1.
  double apparent_viscosity(double shear_rate) const override;

 private:
  double consistency_;
  double flow_index_;
};

}  // namespace partimix::materials
