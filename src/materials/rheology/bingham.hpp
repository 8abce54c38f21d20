#pragma once
// Bingham plastic (Bingham 1922): tau = tau0 + mu_p gamma_dot above the yield stress, so
// eta = tau0 / gamma_dot + mu_p, with the yield-stress part regularised
// (materials/rheology/yield_regularisation.hpp).
#include "materials/rheology.hpp"
#include "materials/rheology/yield_regularisation.hpp"

namespace partimix::materials {

class Bingham final : public Rheology {
 public:
  Bingham(const YieldRegularisation& yield, double plastic_viscosity);
  double apparent_viscosity(double shear_rate) const override;

 private:
  YieldRegularisation yield_;
  double plastic_viscosity_;
};

}  // namespace partimix::materials
