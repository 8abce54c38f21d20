#include "analysis/running_line_fit.hpp"

#include <limits>

namespace partimix::analysis {

// With d = x_n - x_mean(n-1): the means move by d / n and (y_n - y_mean(n-1)) / n, and the sums
// grow by d (x_n - x_mean(n)) and d (y_n - y_mean(n)).
void RunningLineFit::add(double x, double y) {
  ++count_;
  const double n = static_cast<double>(count_);
  const double dx = x - mean_x_;
  mean_x_ += dx / n;
  mean_y_ += (y - mean_y_) / n;
  sum_xx_ += dx * (x - mean_x_);
  sum_xy_ += dx * (y - mean_y_);
}

double RunningLineFit::slope() const {
  if (count_ < 2 || !(sum_xx_ > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  return sum_xy_ / sum_xx_;
}

}  // namespace partimix::analysis
