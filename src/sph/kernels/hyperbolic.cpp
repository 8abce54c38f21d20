#include "sph/kernels/hyperbolic.hpp"

#include <numbers>

namespace partimix::sph {

double Hyperbolic::shape(double q) const {
  if (q < 1.0)
    return q * q * q - 6.0 * q + 6.0;
  if (q < 2.0)
    return (2.0 - q) * (2.0 - q) * (2.0 - q);
  return 0.0;
}

double Hyperbolic::shape_derivative(double q) const {
  if (q < 1.0)
    return 3.0 * q * q - 6.0;
  if (q < 2.0)
    return -3.0 * (2.0 - q) * (2.0 - q);
  return 0.0;
}

double Hyperbolic::normalisation(int dimensions) const {
  return dimensions == 2 ? 1.0 / (3.0 * std::numbers::pi) : 15.0 / (62.0 * std::numbers::pi);
}

}  // namespace partimix::sph
