#include "sph/surface_tension.hpp"

#include <cmath>

namespace partimix::sph {

void compute_colour_gradients(const InterfaceParticles& p, std::size_t count, const CellGrid& grid,
                              const KernelTable& kernel, bool density_weighted,
                              std::span<Vec3> colour_gradient) {
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double vi = p.mass[i] / p.density[i];
    Vec3 gradient = Vec3::Zero();
    grid.for_each_neighbour(
        i, p.position,
        [&](std::size_t j, const Vec3& rij, double r2) {
          if (j == i)
            return;
          const double vj = p.mass[j] / p.density[j];
          const double mixed = density_weighted
                                   ? (p.density[j] * p.colour[i] + p.density[i] * p.colour[j]) /
                                         (p.density[i] + p.density[j])
                                   : 0.5 * (p.colour[i] + p.colour[j]);
          const double r = std::sqrt(r2);
          gradient += (vi * vi + vj * vj) * mixed * kernel.derivative(r) / r * rij;
        },
        count);
    colour_gradient[i] = gradient / vi;
  }
}

void compute_curvatures(const InterfaceParticles& p, std::size_t count, const CellGrid& grid,
                        const KernelTable& kernel, int dimensions, double h, double threshold,
                        std::span<const Vec3> colour_gradient, std::span<double> curvature) {
  const double least = threshold / h;
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    curvature[i] = 0.0;
    const double size = colour_gradient[i].norm();
    if (size <= least)
      continue;
    const Vec3 ni = colour_gradient[i] / size;
    double divergence = 0.0;
    double position_divergence = 0.0;
    grid.for_each_neighbour(
        i, p.position,
        [&](std::size_t j, const Vec3& rij, double r2) {
          const double size_j = colour_gradient[j].norm();
          if (j == i || size_j <= least)
            return;
          const double r = std::sqrt(r2);
          // grad_i W_ij = dW/dr r_ij / r, r_ij = x_i - x_j.
          const Vec3 gradient = kernel.derivative(r) / r * rij;
          const double vj = p.mass[j] / p.density[j];
          divergence += (colour_gradient[j] / size_j - ni).dot(gradient) * vj;
          position_divergence -= (rij - ni * ni.dot(rij)).dot(gradient) * vj;
        },
        count);
    if (position_divergence != 0.0)
      curvature[i] = -(dimensions - 1) * divergence / position_divergence;
  }
}

void smooth_curvatures(const InterfaceParticles& p, std::size_t count, const CellGrid& grid,
                       const KernelTable& kernel, std::span<const Vec3> colour_gradient,
                       std::span<const double> curvature, std::span<double> smoothed) {
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    smoothed[i] = 0.0;
    if (curvature[i] == 0.0)
      continue;
    double sum = 0.0;
    double weight = 0.0;
    grid.for_each_neighbour(
        i, p.position,
        [&](std::size_t j, const Vec3&, double r2) {
          if (curvature[j] == 0.0)
            return;
          const double w =
              colour_gradient[j].norm() * kernel.value(std::sqrt(r2)) * p.mass[j] / p.density[j];
          sum += w * curvature[j];
          weight += w;
        },
        count);
    smoothed[i] = sum / weight;
  }
}

void add_surface_tension(const InterfaceParticles& p, std::size_t count, double sigma,
                         std::span<const Vec3> colour_gradient, std::span<const double> curvature,
                         std::span<Vec3> acceleration) {
  for (std::size_t i = 0; i < count; ++i)
    acceleration[i] += sigma * curvature[i] / p.density[i] * colour_gradient[i];
}

}  // namespace partimix::sph
