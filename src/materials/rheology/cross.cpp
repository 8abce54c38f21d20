#include "materials/rheology/cross.hpp"

#include <cmath>

namespace partimix::materials {

Cross::Cross(double zero_shear_viscosity, double infinite_shear_viscosity, double time_constant,
             double flow_index)
    : eta0_(zero_shear_viscosity),
      eta_inf_(infinite_shear_viscosity),
      lambda_(time_constant),
      n_(flow_index) {}

double Cross::apparent_viscosity(double shear_rate) const {
  return eta_inf_ + (eta0_ - eta_inf_) / (1.0 + std::pow(lambda_ * shear_rate, n_));
}

}  // namespace partimix::materials
