#include "mpm/point_exits.hpp"

namespace partimix::mpm {
namespace {

bool beyond(const std::vector<PointExit>& exits, const Vec3& x) {
  for (const PointExit& exit : exits) {
    if ((x - exit.point).dot(exit.normal) > 0.0)
      return true;
  }
  return false;
}

}  // namespace

double remove_exited(const std::vector<PointExit>& exits, ParticleStore& store,
                     std::vector<std::uint32_t>& order) {
  if (exits.empty())
    return 0.0;
  const std::size_t count = store.size();
  order.resize(count);
  std::size_t kept = 0;
  for (std::uint32_t p = 0; p < count; ++p) {
    if (!beyond(exits, store.position()[p]))
      order[kept++] = p;
  }
  if (kept == count)
    return 0.0;
  double mass = 0.0;
  std::size_t next = kept;
  for (std::uint32_t p = 0; p < count; ++p) {
    if (beyond(exits, store.position()[p])) {
      order[next++] = p;
      mass += store.mass()[p];
    }
  }
  store.reorder(order);
  store.resize(kept);
  return mass;
}

}  // namespace partimix::mpm
