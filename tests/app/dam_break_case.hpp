#pragma once
// A small 3D dam break for the end-to-end tests: a 0.2 m water cube in the corner of a
// 0.6 x 0.3 x 0.5 m tank with an open top, about 3,000 particles, a fraction of a second to run.
#include <string>

namespace partimix::cli_test {

inline constexpr double kDamBreakEnd = 0.05;
inline constexpr double kDamBreakOutputInterval = 0.02;
inline constexpr double kDamBreakSpacing = 0.04;

inline const std::string kDamBreak3D = R"(name: dam_break_3d_small
solver: sph
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.2, -0.2, -0.2]
  max: [0.8, 0.5, 0.8]
time:
  end: 0.05
  output_interval: 0.02
  sample_interval: 0.01
sph:
  spacing: 0.04
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0, 0]
      max: [0.2, 0.2, 0.2]
walls:
  - shape: box
    min: [0, 0, 0]
    max: [0.6, 0.3, 0.5]
    open: [z+]
analyses:
  - type: front_position
    axis: x
)";

}  // namespace partimix::cli_test
