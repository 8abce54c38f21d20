#include "sph/multi_material/surface_heating.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>

namespace partimix::sph {

SurfaceHeating::SurfaceHeating(std::vector<double> flux, int dimensions)
    : flux_(std::move(flux)), dimensions_(dimensions) {
  any_ = std::ranges::any_of(flux_, [](double q) { return q != 0.0; });
}

double SurfaceHeating::flux_of(std::size_t i, std::span<const std::int32_t> material) const {
  return flux_[static_cast<std::size_t>(material[i])];
}

// The root of i's body, halving the path to it.
std::uint32_t SurfaceHeating::root(std::uint32_t i) {
  while (parent_[i] != i) {
    parent_[i] = parent_[parent_[i]];
    i = parent_[i];
  }
  return i;
}

// Joins each particle of a material with a flux to those of its material closer than the mean
// of their smoothing lengths.
void SurfaceHeating::join(const SurfaceHeatingParticles& particles, std::size_t n,
                          const CellGrid& grid) {
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  for (std::size_t i = 0; i < n; ++i) {
    if (flux_of(i, particles.material) == 0.0)
      continue;
    grid.for_each_neighbour(
        i, particles.position,
        [&](std::size_t j, const Vec3&, double r2) {
          const double reach = 0.5 * (particles.h[i] + particles.h[j]);
          if (particles.material[j] != particles.material[i] || r2 >= reach * reach)
            return;
          const std::uint32_t a = root(static_cast<std::uint32_t>(i));
          const std::uint32_t b = root(static_cast<std::uint32_t>(j));
          if (a != b)
            parent_[std::max(a, b)] = std::min(a, b);
        },
        i);
  }
}

// The surface of the disc (per unit depth) or sphere of `volume`.
double SurfaceHeating::surface(double volume) const {
  if (dimensions_ == 2)
    return 2.0 * std::sqrt(std::numbers::pi * volume);
  return std::cbrt(36.0 * std::numbers::pi * volume * volume);
}

void SurfaceHeating::update(const SurfaceHeatingParticles& particles, std::size_t n,
                            const CellGrid& grid, std::span<double> source) {
  join(particles, n, grid);
  body_volume_.assign(n, 0.0);
  body_size_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (flux_of(i, particles.material) == 0.0)
      continue;
    const std::uint32_t body = root(static_cast<std::uint32_t>(i));
    body_volume_[body] += particles.mass[i] / particles.density[i];
    body_size_[body] += 1;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double flux = flux_of(i, particles.material);
    const std::uint32_t body = root(static_cast<std::uint32_t>(i));
    if (flux == 0.0 || body_size_[body] < kSmallestBody) {
      source[i] = 0.0;
      continue;
    }
    const double volume = body_volume_[body];
    source[i] = flux * surface(volume) / volume;
  }
}

}  // namespace partimix::sph
