#pragma once
// A DEM case with one wall, a small truck drum (0.17 m long, tilted, seed 004's optimised blades
// at 78 deg, offsets 100/85/76 deg), for the tests of the truck_drum keys and of `partimix stl`.
// Its lines 20, 21, 27 and 28 are the axis, head_radius, blades and divisions.
#include <string>

namespace partimix::test_support {

inline const std::string kSmallTruckDrumCase = R"(solver: dem
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.2, -0.2, -0.2]
  max: [0.2, 0.2, 0.2]
time:
  end: 0.1
  output_interval: 0.01
dem:
  species:
    - {name: a, density: 2500}
  fill:
    region: {shape: box, min: [-0.02, -0.02, -0.02], max: [0.02, 0.02, 0.02]}
    count: 10
    radius: 0.002
walls:
  - shape: truck_drum
    axis_point: [-0.1, 0, 0]
    axis: [1, 0, 0.2]
    head_radius: 0.05
    front_length: 0.05
    radius: 0.08
    cylinder_length: 0.06
    rear_length: 0.06
    opening_radius: 0.03
    blades: {height: 0.02, thickness: 0.004, helix_angle: 78, offset_angles: [100, 85, 76]}
    divisions: 48
)";

}  // namespace partimix::test_support
