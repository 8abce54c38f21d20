#pragma once
// Cubic B-spline kernel (Monaghan and Lattanzio 1985; the seed's eq. 11):
// f(q) = 1 - 3/2 q^2 + 3/4 q^3 for q < 1, 1/4 (2 - q)^3 for 1 <= q < 2.
// sigma_2 = 10 / (7 pi), sigma_3 = 1 / pi. The seed prints 5 / (14 pi h^2) for the form
// (2 - q)^3 - 4 (1 - q)^3, which is the same kernel.
#include "sph/kernel.hpp"

namespace partimix::sph {

class CubicSpline final : public Kernel {
 public:
  double shape(double q) const override;
  double shape_derivative(double q) const override;
  double normalisation(int dimensions) const override;
};

}  // namespace partimix::sph
