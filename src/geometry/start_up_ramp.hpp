#pragma once
// Smooth start-up of a prescribed speed (docs/motions.md, "Start-up"): the angular speed is
// omega s(t) with s = (1 - cos(pi t / T)) / 2 for t < T and 1 after, so the speed and the
// acceleration start from zero without a jump in speed; the angle is omega S(t), S the integral
// of s.
#include <cmath>
#include <numbers>

namespace partimix::geometry {

class StartUpRamp {
 public:
  explicit StartUpRamp(double ramp_time) : ramp_time_(ramp_time) {}

  // s(t): the fraction of the full speed reached at time t.
  double speed_fraction(double t) const {
    if (t >= ramp_time_)
      return 1.0;
    return 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp_time_));
  }

  // S(t) = integral of s from 0 to t [s]: the angle is omega S(t).
  double equivalent_time(double t) const {
    if (t >= ramp_time_)
      return t - 0.5 * ramp_time_;
    const double pi = std::numbers::pi;
    return 0.5 * t - ramp_time_ / (2.0 * pi) * std::sin(pi * t / ramp_time_);
  }

 private:
  double ramp_time_;
};

}  // namespace partimix::geometry
