#include "materials/rheology/bingham.hpp"

namespace partimix::materials {

Bingham::Bingham(const YieldRegularisation& yield, double plastic_viscosity)
    : yield_(yield), plastic_viscosity_(plastic_viscosity) {}

double Bingham::apparent_viscosity(double shear_rate) const {
  return yield_.viscosity(shear_rate) + plastic_viscosity_;
}

}  // namespace partimix::materials
