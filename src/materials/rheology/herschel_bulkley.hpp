#pragma once
// Herschel-Bulkley fluid (Herschel and Bulkley 1926; the seed's eq. 4): tau = tau0 + K
// gamma_dot^n above the yield stress, so eta = tau0 / gamma_dot + K gamma_dot^(n-1), with the
// yield-stress part regularised (materials/rheology/yield_regularisation.hpp). n = 1 is Bingham.
#include "materials/rheology.hpp"
#include "materials/rheology/power_law.hpp"
#include "materials/rheology/yield_regularisation.hpp"

namespace partimix::materials {

class HerschelBulkley final : public Rheology {
 public:
  HerschelBulkley(const YieldRegularisation& yield, double consistency, double flow_index);
  double apparent_viscosity(double shear_rate) const override;

 private:
  YieldRegularisation yield_;
  PowerLaw power_law_;
};

}  // namespace partimix::materials
