#pragma once
// The box that holds every particle of a run, with periodic axes. On a periodic axis the box
// length is the period: positions are wrapped into [lo, hi) and distances use the nearest image.
// A particle outside the box on a non-periodic axis is lost and stops the run.
#include <array>
#include <cmath>

#include "core/vec.hpp"

namespace partimix {

struct Domain {
  int dimensions = 3;  // 2: the x-y plane, z = 0
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<bool, 3> periodic{false, false, false};

  Vec3 length() const { return hi - lo; }

  // a - b, through the nearest periodic image.
  Vec3 displacement(const Vec3& a, const Vec3& b) const {
    Vec3 d = a - b;
    for (int axis = 0; axis < dimensions; ++axis) {
      if (periodic[axis]) {
        const double period = hi[axis] - lo[axis];
        if (d[axis] > 0.5 * period) {
          d[axis] -= period;
        } else if (d[axis] < -0.5 * period) {
          d[axis] += period;
        }
      }
    }
    return d;
  }

  // Moves a position into [lo, hi) along the periodic axes, by whole periods in one step
  // however far out it is. A non-finite coordinate is left as it is, for the health check to
  // report (particles/health.hpp).
  void wrap(Vec3& x) const {
    for (int axis = 0; axis < dimensions; ++axis) {
      if (periodic[axis] && std::isfinite(x[axis]) && (x[axis] < lo[axis] || x[axis] >= hi[axis])) {
        const double period = hi[axis] - lo[axis];
        x[axis] -= std::floor((x[axis] - lo[axis]) / period) * period;
        if (x[axis] >= hi[axis])  // rounding of a point just below lo
          x[axis] = lo[axis];
        if (x[axis] < lo[axis])
          x[axis] = lo[axis];
      }
    }
  }

  bool contains(const Vec3& x) const {
    for (int axis = 0; axis < dimensions; ++axis) {
      if (!(x[axis] >= lo[axis] && x[axis] <= hi[axis])) {
        return false;
      }
    }
    return true;
  }
};

}  // namespace partimix
