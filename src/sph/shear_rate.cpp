#include "sph/shear_rate.hpp"

#include <cmath>
#include <cstddef>

#include <Eigen/LU>

namespace partimix::sph {
namespace {

struct GradientSums {
  Mat3 velocity = Mat3::Zero();  // sum_j V_j (v_j - v_i) (x) grad W
  Mat3 moment = Mat3::Zero();    // sum_j V_j (x_j - x_i) (x) grad W
};

GradientSums gradient_sums(std::size_t i, const Fields& f, const CellGrid& grid,
                           const KernelTable& kernel) {
  GradientSums sums;
  const Vec3& v_i = f.velocity[i];
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
    if (j == i)
      return;
    const double r = std::sqrt(r2);
    const Vec3 grad = (kernel.derivative(r) / r) * r_ij;
    const double volume = f.mass[j] / f.density[j];
    const Vec3& v_j = is_fluid(f.kind[j]) ? f.velocity[j] : f.wall_velocity[j];
    sums.velocity += volume * (v_j - v_i) * grad.transpose();
    sums.moment -= volume * r_ij * grad.transpose();
  });
  return sums;
}

// M restricted to the plane in 2D (z row and column set to the identity) and inverted; the
// identity where M is singular (a particle with too few neighbours).
Mat3 correction(Mat3 moment, int dimensions) {
  if (dimensions == 2) {
    moment.row(2).setZero();
    moment.col(2).setZero();
    moment(2, 2) = 1.0;
  }
  Mat3 inverse;
  bool invertible = false;
  moment.computeInverseWithCheck(inverse, invertible, 1e-6);
  return invertible ? inverse : Mat3::Identity();
}

}  // namespace

void compute_shear_rates(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& kernel, int dimensions, bool corrected) {
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const GradientSums sums = gradient_sums(i, f, grid, kernel);
    const Mat3 gradient =
        corrected ? Mat3(sums.velocity * correction(sums.moment, dimensions)) : sums.velocity;
    const Mat3 strain_rate = 0.5 * (gradient + gradient.transpose());
    f.shear_rate[i] = std::sqrt(2.0 * strain_rate.squaredNorm());
  }
}

}  // namespace partimix::sph
