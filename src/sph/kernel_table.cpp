#include "sph/kernel_table.hpp"

namespace partimix::sph {

KernelTable::KernelTable(const Kernel& kernel, double h, int dimensions, int intervals)
    : support_radius_(kernel.support() * h),
      inverse_step_(intervals / support_radius_),
      values_(static_cast<std::size_t>(intervals) + 2, 0.0),
      derivatives_(static_cast<std::size_t>(intervals) + 2, 0.0) {
  const double step = support_radius_ / intervals;
  for (int k = 0; k <= intervals; ++k) {
    const double r = k * step;
    values_[static_cast<std::size_t>(k)] = kernel_value(kernel, r, h, dimensions);
    derivatives_[static_cast<std::size_t>(k)] = kernel_derivative(kernel, r, h, dimensions);
  }
}

}  // namespace partimix::sph
