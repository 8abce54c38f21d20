#include "materials/rheology/yield_regularisation.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace partimix::materials {

YieldRegularisation::YieldRegularisation(double yield_stress, const std::string& regularisation,
                                         double exponent)
    : yield_stress_(yield_stress),
      exponent_(exponent),
      papanastasiou_(regularisation == "papanastasiou") {
  if (!papanastasiou_ && regularisation != "biviscous") {
    throw std::invalid_argument("unknown yield-stress regularisation '" + regularisation +
                                "'; expected one of: papanastasiou, biviscous");
  }
}

double YieldRegularisation::viscosity(double shear_rate) const {
  if (yield_stress_ == 0.0) {
    return 0.0;
  }
  return papanastasiou_ ? papanastasiou(shear_rate) : biviscous(shear_rate);
}

// tau0 (1 - exp(-m gd)) / gd, written with expm1 so that it stays accurate for m gd << 1; its
// limit at gd = 0 is tau0 m.
double YieldRegularisation::papanastasiou(double shear_rate) const {
  if (shear_rate == 0.0) {
    return yield_stress_ * exponent_;
  }
  return -yield_stress_ * std::expm1(-exponent_ * shear_rate) / shear_rate;
}

double YieldRegularisation::biviscous(double shear_rate) const {
  if (shear_rate == 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  return yield_stress_ / shear_rate;
}

}  // namespace partimix::materials
