#include "dem/insertion.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

namespace partimix::dem {

namespace {

// Spheres placed so far, hashed by cells of the largest diameter: a candidate meets only
// spheres in the 27 cells around its own.
class PlacedSpheres {
 public:
  explicit PlacedSpheres(double cell) : cell_(cell) {}

  bool overlaps(const Vec3& x, double radius, const Grains& grains) const {
    const auto c = cell_of(x);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (found == cells_.end())
            continue;
          for (const std::size_t j : found->second) {
            const double reach = radius + grains.radius[j];
            if ((grains.position[j] - x).squaredNorm() < reach * reach)
              return true;
          }
        }
    return false;
  }

  void add(const Vec3& x, std::size_t index) {
    const auto c = cell_of(x);
    cells_[key(c[0], c[1], c[2])].push_back(index);
  }

 private:
  std::array<long, 3> cell_of(const Vec3& x) const {
    return {std::lround(std::floor(x.x() / cell_)), std::lround(std::floor(x.y() / cell_)),
            std::lround(std::floor(x.z() / cell_))};
  }
  static std::uint64_t key(long x, long y, long z) {
    const auto part = [](long v) { return static_cast<std::uint64_t>(v + (1L << 20)) & 0x1FFFFF; };
    return part(x) << 42 | part(y) << 21 | part(z);
  }

  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// Refuses a count whose spheres, at the smallest radius, could not fit in the region's bounding
// box even at the densest packing of equal spheres (pi / sqrt(18)): no candidate is drawn then.
void check_capacity(const geometry::Shape& region, const InsertionRequest& request) {
  const Vec3 size = region.upper() - region.lower();
  const double box = size.x() * size.y() * size.z();
  const double spheres =
      request.count * 4.0 / 3.0 * std::numbers::pi * std::pow(request.radius_min, 3);
  const double densest = std::numbers::pi / std::sqrt(18.0);
  if (std::isfinite(box) && spheres > densest * box) {
    throw std::runtime_error(fmt::format(
        "{} spheres of radius {:.3g} m take {:.3g} m^3, more than the region's bounding box "
        "holds at the densest packing ({:.3g} x {:.3g} m^3); make the region larger or the "
        "count smaller",
        request.count, request.radius_min, spheres, densest, box));
  }
}

}  // namespace

Grains insert_random(const geometry::Shape& region, const InsertionRequest& request) {
  check_capacity(region, request);
  std::mt19937_64 random(request.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 lo = region.lower();
  const Vec3 size = region.upper() - lo;
  Grains grains;
  PlacedSpheres placed(2.0 * request.radius_max);
  long attempts = 0;
  for (int failures = 0; failures < request.attempts_per_sphere &&
                         static_cast<int>(grains.position.size()) < request.count;) {
    ++attempts;
    const double radius =
        request.radius_min + (request.radius_max - request.radius_min) * unit(random);
    const Vec3 x = lo + Vec3(unit(random), unit(random), unit(random)).cwiseProduct(size);
    if (region.signed_distance(x) > -radius || placed.overlaps(x, radius, grains)) {
      ++failures;
      continue;
    }
    failures = 0;
    placed.add(x, grains.position.size());
    grains.position.push_back(x);
    grains.radius.push_back(radius);
    grains.species.push_back(request.species);
  }
  if (static_cast<int>(grains.position.size()) < request.count) {
    throw std::runtime_error(fmt::format(
        "only {} of {} spheres fitted into the region without overlap ({} candidates in a row "
        "failed, {} in all); make the region larger or the count smaller",
        grains.position.size(), request.count, request.attempts_per_sphere, attempts));
  }
  return grains;
}

}  // namespace partimix::dem
