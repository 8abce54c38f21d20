#pragma once
// Herschel-Bulkley fluid (Herschel and Bulkley 1926; the seed's eq. 4): tau = tau0 + K
// gamma_dot^n above the yield stress, so eta = tau0 / gamma_dot + K gamma_dot^(n-1), with the
// yield-stress part regularised (sph/rheology/yield_regularisation.hpp). n = 1 is Bingham.
#include "sph/rheology.hpp"
#include "sph/rheology/power_law.hpp"
#include "sph/rheology/yield_regularisation.hpp"

namespace partimix::sph {

class HerschelBulkley final : public Rheology {
 public:
  HerschelBulkley(const YieldRegularisation& yield, double consistency, double flow_index);
  double apparent_viscosity(double shear_rate) const override;

 private:
  YieldRegularisation yield_;
  PowerLaw power_law_;
};

}  // namespace partimix::sph
