#pragma once
// The window of the summary's time averages: the last k revolutions of a body's motion
// (docs/power.md, "Summary").
#include <algorithm>
#include <cmath>

#include "geometry/motion.hpp"

namespace partimix::analysis {

// The period of the slowest turning of a motion [s]: the revolution for planetary motion, the
// rotation otherwise; 0 for a body that does not turn.
inline double revolution_period(const geometry::MotionConfig& motion) {
  const double rpm = motion.type == "planetary" && motion.revolution_rpm != 0.0
                         ? motion.revolution_rpm
                         : motion.rpm;
  return motion.type == "fixed" || rpm == 0.0 ? 0.0 : 60.0 / std::abs(rpm);
}

struct AveragingWindow {
  double from = 0.0;         // [s]
  double to = 0.0;           // [s]
  double revolutions = 0.0;  // the window's length in periods (0 for a body that does not turn)
};

// The last `revolutions` periods before `last`, clipped to start at `first`.
inline AveragingWindow averaging_window(double first, double last, double period,
                                        double revolutions) {
  AveragingWindow window;
  window.to = last;
  window.from = std::max(first, last - revolutions * period);
  window.revolutions = period > 0.0 ? (window.to - window.from) / period : 0.0;
  return window;
}

}  // namespace partimix::analysis
