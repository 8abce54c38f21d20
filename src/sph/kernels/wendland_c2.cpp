#include "sph/kernels/wendland_c2.hpp"

#include <numbers>

namespace partimix::sph {

double WendlandC2::shape(double q) const {
  if (q >= 2.0)
    return 0.0;
  const double a = 1.0 - 0.5 * q;
  return a * a * a * a * (2.0 * q + 1.0);
}

double WendlandC2::shape_derivative(double q) const {
  if (q >= 2.0)
    return 0.0;
  const double a = 1.0 - 0.5 * q;
  return -5.0 * q * a * a * a;
}

double WendlandC2::normalisation(int dimensions) const {
  return dimensions == 2 ? 7.0 / (4.0 * std::numbers::pi) : 21.0 / (16.0 * std::numbers::pi);
}

}  // namespace partimix::sph
