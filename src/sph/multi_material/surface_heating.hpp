#pragma once
// Heat that a material takes in through the surfaces of its bodies (docs/multi-material-sph.md,
// "The scheme", temperature): a material's `surface_heat_flux` q'' [W/m^2] stands for the heat,
// or the vapour, that its surroundings give each of its bodies in proportion to the body's
// surface, as a vapour bubble grows by what the liquid round it releases at its wall. A body is a
// connected set of the material's particles, two joined when closer than the mean of their
// smoothing lengths; its surface is that of the disc (2D, per unit depth: 2 (pi V)^(1/2)) or the
// sphere (3D: (36 pi V^2)^(1/3)) of its volume V = sum m / rho, and the body's heat q'' S is
// shared by its particles in proportion to their volumes: each takes q'' S / V per unit volume.
// A body of fewer than kSmallestBody particles takes none: it is not a resolved bubble but a
// fragment, whose S / V, of the order of one over a particle's size, would heat it without
// bound.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"

namespace partimix::sph {

struct SurfaceHeatingParticles {
  std::span<const Vec3> position;
  std::span<const double> h;
  std::span<const double> mass;
  std::span<const double> density;
  std::span<const std::int32_t> material;
};

class SurfaceHeating {
 public:
  static constexpr int kSmallestBody = 10;

  // flux[m]: q'' of material m [W/m^2]; 0 for a material without.
  SurfaceHeating(std::vector<double> flux, int dimensions);

  bool any() const { return any_; }

  // The volumetric heating q'' S / V [W/m^3] of each of the n particles (0 for those of a
  // material without a flux) into `source`. The grid is built on the positions, its radius at
  // least the largest smoothing length. Allocates only when n grows.
  void update(const SurfaceHeatingParticles& particles, std::size_t n, const CellGrid& grid,
              std::span<double> source);

 private:
  double flux_of(std::size_t i, std::span<const std::int32_t> material) const;
  std::uint32_t root(std::uint32_t i);
  void join(const SurfaceHeatingParticles& particles, std::size_t n, const CellGrid& grid);
  double surface(double volume) const;

  std::vector<double> flux_;
  int dimensions_;
  bool any_ = false;
  std::vector<std::uint32_t> parent_;  // union-find of the bodies
  std::vector<double> body_volume_;    // by root
  std::vector<int> body_size_;         // by root: its particles
};

}  // namespace partimix::sph
