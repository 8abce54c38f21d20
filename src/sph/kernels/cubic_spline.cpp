#include "sph/kernels/cubic_spline.hpp"

#include <numbers>

namespace partimix::sph {

double CubicSpline::shape(double q) const {
  if (q < 1.0)
    return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
  if (q < 2.0)
    return 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
  return 0.0;
}

double CubicSpline::shape_derivative(double q) const {
  if (q < 1.0)
    return -3.0 * q + 2.25 * q * q;
  if (q < 2.0)
    return -0.75 * (2.0 - q) * (2.0 - q);
  return 0.0;
}

double CubicSpline::normalisation(int dimensions) const {
  return dimensions == 2 ? 10.0 / (7.0 * std::numbers::pi) : 1.0 / std::numbers::pi;
}

}  // namespace partimix::sph
