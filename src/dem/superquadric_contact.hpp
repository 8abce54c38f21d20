#pragma once
// Contact detection between two superquadric grains by the midway point (docs/dem.md,
// "Superquadric grains"; seed eqs. 2-4 after Podlozhnyuk, Pirker & Kloss 2017, Comput. Part.
// Mech. 4, 101): grad G_i + mu^2 grad G_j = 0, G_i = G_j for X and mu, with G = N - 1 the
// grains' gauges (dem/superquadric_gauge.hpp), by Newton's method damped Levenberg-Marquardt's
// way; then the surface points along the normal line through X. Bounding spheres and oriented
// boxes reject distant pairs first. A pure function of its inputs that does not allocate.
#include <optional>

#include "core/vec.hpp"
#include "dem/superquadric.hpp"

namespace partimix::dem {

struct GrainPose {
  const Superquadric* shape;
  Vec3 centre;
  Mat3 rotation;  // body to world
};

// The midway point and multiplier of a previous step's contact: Newton's start (warm start).
struct MidwayStart {
  Vec3 midway;
  double mu = 1.0;
};

struct ContactTolerance {
  // On Newton's residual, |L (grad G_i + mu^2 grad G_j)| and |G_i - G_j| with L the smallest
  // half-axis of the two grains.
  double residual = 1e-10;
  int max_iterations = 40;  // Newton steps from each start
};

struct SuperquadricContact {
  bool touching = false;  // G_i(X) < 0 and G_j(X) < 0 at the converged midway point
  // False when Newton, from the warm start and from the centre line, or the search for a
  // surface point missed its tolerance. True for pairs the bounding tests reject.
  bool converged = true;
  Vec3 normal = Vec3::Zero();  // unit, out of grain i towards grain j, world frame
  double overlap = 0.0;        // alpha - beta along the normal, > 0 when touching
  Vec3 point = Vec3::Zero();   // the contact point (X_i + X_j) / 2, world frame
  Vec3 midway = Vec3::Zero();  // X, world frame (for the next step's warm start)
  double mu = 1.0;             // the multiplier at X (for the warm start)
  int iterations = 0;          // Newton steps, 0 when the bounding tests reject the pair
  bool near = false;           // the bounding tests passed: Newton ran, midway and mu hold
  // When apart: a lower bound on the distance between the two surfaces, 0 when none is known
  // (docs/dem.md, "Pairs known apart").
  double gap = 0.0;
};

// The contact of grain i with grain j: two ellipsoids by their contact function
// (dem/ellipsoid_contact.hpp, warm-started from start->mu), any other pair by
// find_midway_contact.
SuperquadricContact find_contact(const GrainPose& i, const GrainPose& j,
                                 const std::optional<MidwayStart>& start,
                                 const ContactTolerance& tolerance = {});

// The contact of grain i with grain j by the midway point's Newton iteration, started from
// `start` when given (and from the centre line if that fails). Any superquadrics.
SuperquadricContact find_midway_contact(const GrainPose& i, const GrainPose& j,
                                        const std::optional<MidwayStart>& start,
                                        const ContactTolerance& tolerance = {});

}  // namespace partimix::dem
