#include "materials/rheology/power_law.hpp"

#include <cmath>

namespace partimix::materials {

PowerLaw::PowerLaw(double consistency, double flow_index)
    : consistency_(consistency), flow_index_(flow_index) {}

// pow(0, n - 1) is +infinity for n < 1, 1 for n = 1 and 0 for n > 1 (C99 Annex F).
double PowerLaw::apparent_viscosity(double shear_rate) const {
  return consistency_ * std::pow(shear_rate, flow_index_ - 1.0);
}

}  // namespace partimix::materials
