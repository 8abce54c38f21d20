#include "sph/free_surface.hpp"

#include <array>

#include "particles/cell_grid.hpp"

namespace partimix::sph {

bool has_free_surface(const ParticleStore& store, const Domain& domain, double spacing) {
  CellGrid grid(domain, 2.0 * spacing);
  grid.build(store.position());
  const int directions = 2 * domain.dimensions;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    std::array<bool, 6> covered{};
    grid.for_each_neighbour(i, store.position(), [&](std::size_t, const Vec3& r_ij, double) {
      for (int axis = 0; axis < domain.dimensions; ++axis) {
        const double ahead = -r_ij[axis];  // x_j - x_i along the axis
        if (ahead >= 0.5 * spacing)
          covered[2 * axis] = true;
        if (ahead <= -0.5 * spacing)
          covered[2 * axis + 1] = true;
      }
    });
    for (int d = 0; d < directions; ++d) {
      if (!covered[d])
        return true;
    }
  }
  return false;
}

}  // namespace partimix::sph
