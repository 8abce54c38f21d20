#pragma once
// A kernel tabulated in q = r / h once, for any smoothing length (docs/multi-material-sph.md,
// "Variable smoothing length"): W(r, h) = sigma_d / h^d f(q), dW/dr = sigma_d / h^(d+1) f'(q),
// and dW/dh = -sigma_d / h^(d+1) (d f(q) + q f'(q)). KernelTable (sph/kernel_table.hpp) is the
// same for one fixed h.
#include <cstddef>
#include <vector>

#include "sph/kernel.hpp"

namespace partimix::sph {

class ScaledKernel {
 public:
  ScaledKernel(const Kernel& kernel, int dimensions, int intervals = 4096);

  double support() const { return support_; }  // in units of h
  double value(double r, double h) const;
  double derivative(double r, double h) const;    // dW/dr
  double h_derivative(double r, double h) const;  // dW/dh

 private:
  double interpolate(const std::vector<double>& table, double q) const;
  double scale(double h) const;  // sigma_d / h^d

  int dimensions_;
  double support_;
  double normalisation_;
  double inverse_step_;
  std::vector<double> shape_;
  std::vector<double> shape_derivative_;
};

}  // namespace partimix::sph
