#pragma once
// The contacts of a grain with a surface of several faces, from one candidate per face
// (docs/dem.md, "Walls of several faces"): a candidate on the boundary of its face that is also
// a point of a deeper candidate's face is no contact of its own (it is not a local minimum of the
// distance over the surface: the deeper face holds points nearer still); the others are kept,
// the deepest first.
#include <cstddef>
#include <span>

#include "geometry/surface.hpp"

namespace partimix::geometry {

// True when a comes before b: the smaller gap, then the smaller face id (a strict total order,
// so that of candidates that shadow one another exactly one survives).
inline bool deeper(const SurfacePoint& a, const SurfacePoint& b) {
  return a.gap < b.gap || (a.gap == b.gap && a.face < b.face);
}

// Sorts `candidates` deepest first by the surface point `point_of` gives for each (insertion:
// a handful of candidates).
template <class Candidate, class PointOf>
void sort_deepest_first(std::span<Candidate> candidates, PointOf point_of) {
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    const Candidate moving = candidates[k];
    std::size_t j = k;
    for (; j > 0 && deeper(point_of(moving), point_of(candidates[j - 1])); --j)
      candidates[j] = candidates[j - 1];
    candidates[j] = moving;
  }
}

inline void sort_deepest_first(std::span<SurfacePoint> candidates) {
  sort_deepest_first(candidates, [](const SurfacePoint& p) -> const SurfacePoint& { return p; });
}

// Sorts `candidates` deepest first (by the surface point `point_of` gives for each), drops those
// `surface.shadowed` by a deeper one, and copies the first out.size() survivors to `out`;
// returns their number. No allocation.
template <class Candidate, class PointOf>
int select_contacts(const Surface& surface, std::span<Candidate> candidates,
                    std::span<Candidate> out, PointOf point_of) {
  sort_deepest_first(candidates, point_of);
  int kept = 0;
  for (std::size_t k = 0; k < candidates.size() && kept < static_cast<int>(out.size()); ++k) {
    bool own = true;
    for (std::size_t j = 0; j < k && own; ++j)
      own = !surface.shadowed(point_of(candidates[k]), point_of(candidates[j]));
    if (own)
      out[kept++] = candidates[k];
  }
  return kept;
}

inline int select_contacts(const Surface& surface, std::span<SurfacePoint> candidates,
                           std::span<SurfacePoint> out) {
  return select_contacts(surface, candidates, out,
                         [](const SurfacePoint& p) -> const SurfacePoint& { return p; });
}

}  // namespace partimix::geometry
