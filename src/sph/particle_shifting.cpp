#include "sph/particle_shifting.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace partimix::sph {

namespace {

// Monaghan's (2000) artificial-pressure weights R (W_ij / W(dp))^n with R = 0.2, n = 4.
constexpr double kPairWeight = 0.2;
constexpr double kLargestShiftInSpacings = 0.1;

// The unit outward normal of a free surface at a particle: against the plain concentration
// gradient; zero where that vanishes.
Vec3 outward_normal(const Concentration& c) {
  const double length = c.plain_gradient.norm();
  return length > 0.0 ? Vec3(-c.plain_gradient / length) : Vec3::Zero();
}

// The free surface's outward normal seen from particle i: the kernel-weighted mean of the normals
// of the surface particles within its support, its own included (averaging takes out most of
// the tilt that the disorder of the particles gives each single normal); zero far from a
// surface.
Vec3 surface_normal_at(std::size_t i, const Fields& f, std::size_t fluid_count,
                       const CellGrid& grid, const KernelTable& kernel,
                       const ShiftingScratch& scratch) {
  Vec3 sum = scratch.surface[i] != 0 ? Vec3(kernel.value(0.0) * scratch.normal[i]) : Vec3::Zero();
  grid.for_each_neighbour(
      i, f.position,
      [&](std::size_t j, const Vec3&, double r2) {
        if (j != i && scratch.surface[j] != 0)
          sum += kernel.value(std::sqrt(r2)) * scratch.normal[j];
      },
      fluid_count);
  const double length = sum.norm();
  return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

Vec3 capped(const Vec3& shift, double largest) {
  const double length = shift.norm();
  return length > largest ? Vec3(shift * (largest / length)) : shift;
}

}  // namespace

Concentration concentration_of(std::size_t i, const Fields& f, const CellGrid& grid,
                               const KernelTable& kernel, const Parameters& p) {
  const double w_spacing = kernel.value(p.spacing);
  Concentration c;
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
    if (j == i)
      return;
    const double r = std::sqrt(r2);
    const Vec3 grad = (kernel.derivative(r) / r) * r_ij;
    const double volume = f.mass[j] / f.density[j];
    const double ratio = kernel.value(r) / w_spacing;
    const double ratio2 = ratio * ratio;
    c.plain_gradient += volume * grad;
    c.gradient += (volume * (1.0 + kPairWeight * ratio2 * ratio2)) * grad;
    c.position_divergence -= volume * r_ij.dot(grad);
  });
  return c;
}

void shift_particles(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                     const KernelTable& kernel, const Parameters& p, const ShiftingStep& settings,
                     double dt, ShiftingScratch& scratch) {
  scratch.shift.resize(fluid_count);
  scratch.normal.resize(fluid_count);
  scratch.surface.resize(fluid_count);
  const double diffusion = settings.coefficient * p.h * settings.speed * dt;
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const Concentration c = concentration_of(i, f, grid, kernel, p);
    scratch.shift[i] = -diffusion * c.gradient;
    scratch.normal[i] = outward_normal(c);
    scratch.surface[i] = at_free_surface(c.position_divergence, p.dimensions) ? 1 : 0;
  }
  const double largest = kLargestShiftInSpacings * p.spacing;
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    Vec3& shift = scratch.shift[i];
    const Vec3 normal = surface_normal_at(i, f, fluid_count, grid, kernel, scratch);
    shift = capped(shift - shift.dot(normal) * normal, largest);
  }
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    f.position[i] += scratch.shift[i];
  }
}

}  // namespace partimix::sph
