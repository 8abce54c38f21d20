#include "materials/rheology/carreau.hpp"

#include <cmath>

namespace partimix::materials {

CarreauYasuda::CarreauYasuda(double zero_shear_viscosity, double infinite_shear_viscosity,
                             double time_constant, double flow_index, double yasuda_exponent)
    : eta0_(zero_shear_viscosity),
      eta_inf_(infinite_shear_viscosity),
      lambda_(time_constant),
      n_(flow_index),
      a_(yasuda_exponent) {}

double CarreauYasuda::apparent_viscosity(double shear_rate) const {
  const double thinning = std::pow(1.0 + std::pow(lambda_ * shear_rate, a_), (n_ - 1.0) / a_);
  return eta_inf_ + (eta0_ - eta_inf_) * thinning;
}

}  // namespace partimix::materials
