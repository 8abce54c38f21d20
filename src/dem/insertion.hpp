#pragma once
// Random insertion of spheres without overlap into a region (docs/dem.md, "Filling"): random
// sequential addition, each candidate centre drawn uniformly inside the region at least its
// radius from the region's surface and kept when it overlaps no sphere placed before.
// Superquadrics get a random orientation (uniform over all rotations) each, their surfaces
// stay inside the region (its signed distance climbed over the surface), and a candidate is
// refused only when its shape touches a placed grain's (the midway point,
// dem/superquadric_contact.hpp).
#include <cstdint>
#include <optional>

#include "dem/config.hpp"
#include "dem/superquadric.hpp"
#include "geometry/shape.hpp"

namespace partimix::dem {

struct InsertionRequest {
  int count = 0;
  double radius_min = 0.0;  // radii uniform in [min, max]; min = max: one size
  double radius_max = 0.0;
  std::uint32_t seed = 1;
  int species = 0;
  // Gives up (throws) after this many failed candidates in a row: 1000 stopped flat spheroids
  // (sigma = 0.25) at 17% of a drum, where 10,000 reach the seed's 21% (docs/dem.md, "Filling").
  int attempts_per_grain = 10000;
  std::optional<Superquadric> shape;  // superquadrics (radius: its bounding radius); none: spheres
};

// Throws std::runtime_error naming how many grains fitted when the region is too full, at once
// when the spheres' volume exceeds what the region's bounding box could hold at the densest
// packing. The work is at most (count + 1) * attempts_per_grain candidates, and far less when
// the region fills up: the insertion stops at the first run of attempts_per_grain failures.
Grains insert_random(const geometry::Shape& region, const InsertionRequest& request);

// The largest attempts_per_grain a case may ask for: a full region then stops the fill after
// some seconds at most.
inline constexpr int kMostAttempts = 1000000;

}  // namespace partimix::dem
