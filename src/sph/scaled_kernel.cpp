#include "sph/scaled_kernel.hpp"

#include <cmath>

namespace partimix::sph {

ScaledKernel::ScaledKernel(const Kernel& kernel, int dimensions, int intervals)
    : dimensions_(dimensions),
      support_(kernel.support()),
      normalisation_(kernel.normalisation(dimensions)),
      inverse_step_(intervals / kernel.support()) {
  shape_.resize(static_cast<std::size_t>(intervals) + 1);
  shape_derivative_.resize(shape_.size());
  for (std::size_t k = 0; k < shape_.size(); ++k) {
    const double q = static_cast<double>(k) / inverse_step_;
    shape_[k] = kernel.shape(q);
    shape_derivative_[k] = kernel.shape_derivative(q);
  }
}

double ScaledKernel::interpolate(const std::vector<double>& table, double q) const {
  const double s = q * inverse_step_;
  const auto k = static_cast<std::size_t>(s);
  if (k + 1 >= table.size())
    return 0.0;
  const double t = s - static_cast<double>(k);
  return table[k] + t * (table[k + 1] - table[k]);
}

double ScaledKernel::scale(double h) const {
  double power = h;
  for (int d = 1; d < dimensions_; ++d)
    power *= h;
  return normalisation_ / power;
}

double ScaledKernel::value(double r, double h) const {
  return scale(h) * interpolate(shape_, r / h);
}

double ScaledKernel::derivative(double r, double h) const {
  return scale(h) / h * interpolate(shape_derivative_, r / h);
}

double ScaledKernel::h_derivative(double r, double h) const {
  const double q = r / h;
  return -scale(h) / h *
         (dimensions_ * interpolate(shape_, q) + q * interpolate(shape_derivative_, q));
}

}  // namespace partimix::sph
