#pragma once
// SPH smoothing kernels (docs/sph.md, "Kernels"). A kernel is its dimensionless shape f(q),
// q = r / h, with compact support q < support(), and its normalisation sigma_d such that
// W(r, h) = sigma_d / h^d f(r / h) integrates to one in d dimensions.
#include <string>

#include "core/registry.hpp"

namespace partimix::sph {

class Kernel {
 public:
  virtual ~Kernel() = default;
  virtual double support() const { return 2.0; }
  virtual double shape(double q) const = 0;
  virtual double shape_derivative(double q) const = 0;  // df/dq
  virtual double normalisation(int dimensions) const = 0;
};

// W(r, h) and dW/dr in `dimensions` dimensions, evaluated directly (tests, set-up).
double kernel_value(const Kernel& kernel, double r, double h, int dimensions);
double kernel_derivative(const Kernel& kernel, double r, double h, int dimensions);

// Kernels by name: cubic_spline, wendland_c2, hyperbolic.
const Registry<Kernel>& kernel_registry();

}  // namespace partimix::sph
