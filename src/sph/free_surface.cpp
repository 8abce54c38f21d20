#include "sph/free_surface.hpp"

#include <algorithm>
#include <vector>

#include "particles/cell_grid.hpp"

namespace partimix::sph {

bool has_free_surface(const ParticleStore& store, const Domain& domain, double support) {
  CellGrid grid(domain, support);
  grid.build(store.position());
  std::vector<std::size_t> counts;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    std::size_t count = 0;
    grid.for_each_neighbour(i, store.position(),
                            [&count](std::size_t, const Vec3&, double) { ++count; });
    counts.push_back(count);
  }
  if (counts.empty())
    return false;
  const auto [fewest, most] = std::minmax_element(counts.begin(), counts.end());
  return 4 * *fewest < 3 * *most;
}

}  // namespace partimix::sph
