#pragma once
// The yield-stress part tau0 / gamma_dot of the apparent viscosity of Bingham and
// Herschel-Bulkley fluids (docs/rheology.md, "Yield stress"), made usable at gamma_dot = 0:
// - papanastasiou: tau0 (1 - exp(-m gamma_dot)) / gamma_dot (Papanastasiou 1987),
//   which tends to tau0 m as gamma_dot -> 0;
// - biviscous: the plain tau0 / gamma_dot, +infinity at gamma_dot = 0; the bound
//   viscosity_max caps it, giving the bi-viscous model (O'Donovan and Tanner 1984).
#include <string>

namespace partimix::materials {

class YieldRegularisation {
 public:
  // `regularisation` is "papanastasiou" or "biviscous" (std::invalid_argument otherwise);
  // `exponent` is Papanastasiou's m [s].
  YieldRegularisation(double yield_stress, const std::string& regularisation, double exponent);
  // The yield-stress viscosity [Pa s] at shear rate gamma_dot >= 0 [1/s].
  double viscosity(double shear_rate) const;

 private:
  double papanastasiou(double shear_rate) const;
  double biviscous(double shear_rate) const;

  double yield_stress_;
  double exponent_;
  bool papanastasiou_;
};

}  // namespace partimix::materials
