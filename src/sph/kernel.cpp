#include "sph/kernel.hpp"

#include <cmath>

namespace partimix::sph {

double kernel_value(const Kernel& kernel, double r, double h, int dimensions) {
  return kernel.normalisation(dimensions) / std::pow(h, dimensions) * kernel.shape(r / h);
}

double kernel_derivative(const Kernel& kernel, double r, double h, int dimensions) {
  return kernel.normalisation(dimensions) / std::pow(h, dimensions + 1) *
         kernel.shape_derivative(r / h);
}

}  // namespace partimix::sph
