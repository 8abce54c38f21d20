#pragma once
// Settings of the bed measurements (docs/mixing.md, "Measurements of a granular bed";
// docs/case-reference.md, "analyses"): packing_fraction, velocity_profile, angle_of_repose,
// mass_in_region, height_profile and orientation_order. They sit apart from the analyses so that
// AnalysisOptions and the case's AnalysisSpec can hold them.
#include <limits>

#include "core/vec.hpp"

namespace partimix::analysis {

// packing_fraction: an axis-aligned box [lo, hi]. A flat z side (lo.z = hi.z, 2D runs) makes it
// a rectangle of the x-y plane, and the fraction an area fraction of discs.
struct PackingBox {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};

// velocity_profile: the segment from `start` to `end` cut into `bins` equal lengths; particles
// within width/2 of the segment count. The measured component is velocity . direction
// (direction normalised on use), or the speed |v| when `speed` is true.
struct ProfileLine {
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::UnitX();
  int bins = 10;
  double width = 0.0;
  bool speed = true;
  Vec3 direction = Vec3::UnitX();
};

// angle_of_repose: the drum axis (through `centre`, along `axis`), the direction of gravity
// `down` (its part normal to the axis is used), the number of bins across the bed, and the
// fraction `trim` of the surface width left out at each end of the line fit.
struct ReposeSection {
  Vec3 axis = Vec3::UnitZ();
  Vec3 centre = Vec3::Zero();
  Vec3 down = -Vec3::UnitY();
  int bins = 20;
  double trim = 0.2;
};

// mass_in_region: an axis-aligned box [lo, hi] (faces included; a flat z side in 2D runs), and
// the span [fit_from, fit_until] of sample times over which the discharge rate is fitted.
struct MassRegion {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  double fit_from = 0.0;                                       // [s]
  double fit_until = std::numeric_limits<double>::infinity();  // [s]
};

// mass_flux: the plane through `point` with unit `normal`, the band of `width` about it, and the
// time from which the mean flux is taken.
struct FluxPlane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = -Vec3::UnitY();
  double width = 0.0;         // [m]
  double average_from = 0.0;  // [s]
};

// height_profile: [from, to] along the coordinate `axis` (0, 1, 2 for x, y, z) cut into `bins`
// equal bins; the height is the coordinate `vertical`.
struct HeightLine {
  int axis = 0;
  int vertical = 1;
  double from = 0.0;  // [m]
  double to = 1.0;    // [m]
  int bins = 10;
};

// orientation_order: the reference direction e of the alignment: the unit `direction`, or, when
// `velocity`, each grain's own direction of motion (grains not faster than `min_speed` are left
// out of the alignment), relative to a frame turning at `frame_angular_velocity` about
// `frame_point` when `rotating_frame` (a drum: then the flowing layer alone moves).
struct OrientationReference {
  bool velocity = true;
  Vec3 direction = Vec3::UnitX();
  double min_speed = 0.0;  // [m/s]
  bool rotating_frame = false;
  Vec3 frame_point = Vec3::Zero();
  Vec3 frame_angular_velocity = Vec3::Zero();  // [rad/s]
};

}  // namespace partimix::analysis
