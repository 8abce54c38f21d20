#pragma once
// Speeds in revolutions per minute, as mixer engineers give them.
#include <numbers>

namespace partimix::geometry {

inline double radians_per_second(double rpm) {
  return rpm * 2.0 * std::numbers::pi / 60.0;
}

}  // namespace partimix::geometry
