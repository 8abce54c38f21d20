#pragma once
// A kernel tabulated for one smoothing length and dimension, for the hot loops: W(r) and
// dW/dr by linear interpolation on a uniform grid in q (docs/sph.md, "Kernels": with 4096
// intervals the relative error is below 1e-6). Any registered kernel costs the same per pair.
#include <vector>

#include "sph/kernel.hpp"

namespace partimix::sph {

class KernelTable {
 public:
  KernelTable(const Kernel& kernel, double h, int dimensions, int intervals = 4096);

  double support_radius() const { return support_radius_; }

  double value(double r) const { return interpolate(values_, r); }
  double derivative(double r) const { return interpolate(derivatives_, r); }  // dW/dr

 private:
  double interpolate(const std::vector<double>& table, double r) const {
    const double s = r * inverse_step_;
    const auto k = static_cast<std::size_t>(s);
    if (k + 1 >= table.size())
      return 0.0;
    const double t = s - static_cast<double>(k);
    return table[k] + t * (table[k + 1] - table[k]);
  }

  double support_radius_;
  double inverse_step_;
  std::vector<double> values_;
  std::vector<double> derivatives_;
};

}  // namespace partimix::sph
