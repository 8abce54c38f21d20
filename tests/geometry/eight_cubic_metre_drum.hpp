#pragma once
// The truck drum of the geometry tests: an 8 m³ drum's proportions (head 0.9 m, the cylinder
// 1.15 m for 1.6 m, the cones 1.8 and 2.0 m long, the opening 0.35 m), blades 0.25 m high and
// 8 mm thick, seed 004's optimised blades (78°, offsets 100/85/76°).
#include <numbers>

#include "geometry/truck_drum.hpp"

namespace partimix::geometry {

inline TruckDrumParameters eight_cubic_metre_drum() {
  constexpr double degree = std::numbers::pi / 180.0;
  TruckDrumParameters p;
  p.head_radius = 0.9;
  p.front_length = 1.8;
  p.radius = 1.15;
  p.cylinder_length = 1.6;
  p.rear_length = 2.0;
  p.opening_radius = 0.35;
  p.helix_angle = 78.0 * degree;
  p.blade_height = 0.25;
  p.blade_thickness = 0.008;
  p.offset_angles = {100.0 * degree, 85.0 * degree, 76.0 * degree};
  return p;
}

}  // namespace partimix::geometry
