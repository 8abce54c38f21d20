#pragma once
// Points drawn uniformly in a domain, for the neighbour-search tests.
#include <random>
#include <vector>

#include "particles/domain.hpp"

namespace partimix {

inline std::vector<Vec3> random_points(const Domain& domain, std::size_t count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> points(count, Vec3::Zero());
  for (auto& x : points) {
    for (int axis = 0; axis < domain.dimensions; ++axis) {
      std::uniform_real_distribution<double> u(domain.lo[axis], domain.hi[axis]);
      x[axis] = u(rng);
    }
  }
  return points;
}

}  // namespace partimix
