#pragma once
// A case of 100 grains filled into a small open box and settled for 0.05 s: the DEM case of the
// end-to-end tests of bad input and interrupts.
#include <string>

namespace partimix::cli_test {

inline const std::string kGrainsInABox = R"(name: grains
solver: dem
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.06, -0.06, -0.01]
  max: [0.06, 0.06, 0.12]
time:
  end: 0.01
  output_interval: 0.005
dem:
  species:
    - {name: sand, density: 2500, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
  interactions:
    particle: {restitution: 0.5, friction: 0.5}
  fill:
    region: {shape: box, min: [-0.04, -0.04, 0.0], max: [0.04, 0.04, 0.08]}
    count: 100
    radius: 0.004
    settle_time: 0.05
walls:
  - shape: box
    min: [-0.05, -0.05, 0]
    max: [0.05, 0.05, 0.1]
    open: [z+]
    material: {youngs_modulus: 1.0e7, poisson_ratio: 0.3}
)";

}  // namespace partimix::cli_test
