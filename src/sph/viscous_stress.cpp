#include "sph/viscous_stress.hpp"

#include <algorithm>
#include <cmath>

#include "sph/pair_rates.hpp"
#include "sph/velocity_gradient.hpp"

namespace partimix::sph {
namespace {

// Fluid particles: shear rate, apparent viscosity and eta_a G^T. Returns the largest viscosity.
double fluid_stresses(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                      const KernelTable& kernel, const materials::BoundedRheology& rheology,
                      int dimensions, bool corrected) {
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
  double largest = 0.0;
#pragma omp parallel for schedule(dynamic, 512) reduction(max : largest)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const Mat3 gradient = velocity_gradient(i, f, grid, kernel, dimensions, corrected);
    f.shear_rate[i] = shear_rate_of(0.5 * (gradient + gradient.transpose()));
    f.viscosity[i] = rheology.viscosity(f.shear_rate[i]);
    f.viscous_stress[i] = f.viscosity[i] * gradient.transpose();
    largest = std::max(largest, f.viscosity[i]);
  }
  return largest;
}

// Wall particles: the kernel-weighted mean of the fluid neighbours' stresses, as Adami et al.
// (2012) extrapolate the pressure (eq. 27 without the body-force term); zero with none.
void wall_stresses(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                   const KernelTable& kernel) {
  const auto first = static_cast<std::ptrdiff_t>(fluid_count);
  const auto n = static_cast<std::ptrdiff_t>(f.position.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = first; ii < n; ++ii) {
    const auto w = static_cast<std::size_t>(ii);
    double weight = 0.0;
    Mat3 stress = Mat3::Zero();
    auto gather = [&](std::size_t j, const Vec3&, double r2) {
      const double W = kernel.value(std::sqrt(r2));
      weight += W;
      stress += W * f.viscous_stress[j];
    };
    grid.for_each_neighbour(w, f.position, gather, fluid_count);
    f.viscous_stress[w] = weight > 0.0 ? Mat3(stress / weight) : Mat3::Zero();
  }
}

}  // namespace

double compute_viscous_stress(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                              const KernelTable& gradient_kernel, const KernelTable& kernel,
                              const materials::BoundedRheology& rheology, int dimensions,
                              bool corrected) {
  const double largest =
      fluid_stresses(f, fluid_count, grid, gradient_kernel, rheology, dimensions, corrected);
  wall_stresses(f, fluid_count, grid, kernel);
  return largest;
}

void compute_stress_divergence(const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                               const KernelTable& gradient_kernel,
                               std::vector<Vec3>& acceleration) {
  acceleration.resize(std::max(acceleration.size(), fluid_count));
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double inverse_density_i = 1.0 / f.density[i];
    const Mat3 tau_i = f.viscous_stress[i] * (inverse_density_i * inverse_density_i);
    Vec3 sum = Vec3::Zero();
    grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
      if (j == i)
        return;
      const double r = std::sqrt(r2);
      const Vec3 grad = (gradient_kernel.derivative(r) / r) * r_ij;
      sum += f.mass[j] * stress_pair_term(tau_i, j, 1.0 / f.density[j], grad, f);
    });
    acceleration[i] = sum;
  }
}

}  // namespace partimix::sph
