#pragma once
// Newtonian fluid: eta = mu, whatever the shear rate (docs/rheology.md, "Newtonian").
#include "materials/rheology.hpp"

namespace partimix::materials {

class Newtonian final : public Rheology {
 public:
  explicit Newtonian(double viscosity);
  double apparent_viscosity(double shear_rate) const override;

 private:
  double viscosity_;
};

}  // namespace partimix::materials
