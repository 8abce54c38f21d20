#pragma once
// The options of the truck drum's measurements (docs/truck-drum.md, "Measurements"):
// drum_segregation and drum_discharge read the grains' places along the drum's axis and from it,
// which a rotation about that axis leaves as they are.
#include <cmath>
#include <limits>
#include <memory>

#include "geometry/truck_drum_shape.hpp"

namespace partimix::analysis {

struct DrumMeasures {
  std::shared_ptr<const geometry::TruckDrumShape> drum;  // the wall measured
  int bins = 10;           // drum_segregation: axial slices of the drum's length
  int coarse_species = 0;  // the species index of the coarse aggregate
  double threshold = 4.0;  // drum_segregation: the segregation degree a design must meet [%]
  double mixing_until = std::numeric_limits<double>::infinity();  // [s]: the summary's sample
  double average_from = std::numeric_limits<double>::infinity();  // [s]: segregation_mean's start
  double fit_from = 0.0;                                          // drum_discharge's fit [s]
  double fit_until = std::numeric_limits<double>::infinity();     // [s]
};

// The place of x along the drum's axis from its head (z) and its distance from the axis (rho).
struct DrumPlace {
  double z = 0.0;
  double rho = 0.0;
  bool inside = false;  // within the shell's cavity (blades included)
};

inline DrumPlace drum_place(const geometry::TruckDrumShape& drum, const Vec3& x) {
  const Vec3 local = drum.to_drum(x);
  return {local.z(), std::hypot(local.x(), local.y()), drum.drum().shell_distance(local) < 0.0};
}

}  // namespace partimix::analysis
