#pragma once
// A least-squares straight line y = a + b x through points added one at a time (docs/mixing.md,
// "Mass in a region and discharge rate"), with the slope
//   b = sum (x_i - x_mean)(y_i - y_mean) / sum (x_i - x_mean)^2.
// The means and the two sums are updated in place as each point comes (Welford's updates), so the
// fit keeps no points and does not lose digits to cancellation when x is large (late times).
#include <cstdint>

namespace partimix::analysis {

class RunningLineFit {
 public:
  void add(double x, double y);
  std::int64_t count() const { return count_; }
  // b; NaN with fewer than two points or when every x is the same.
  double slope() const;

 private:
  std::int64_t count_ = 0;
  double mean_x_ = 0.0;
  double mean_y_ = 0.0;
  double sum_xx_ = 0.0;  // sum (x_i - x_mean)^2
  double sum_xy_ = 0.0;  // sum (x_i - x_mean)(y_i - y_mean)
};

}  // namespace partimix::analysis
