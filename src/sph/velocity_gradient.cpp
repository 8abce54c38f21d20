#include "sph/velocity_gradient.hpp"

#include <cmath>

#include <Eigen/LU>

namespace partimix::sph {
namespace {

struct GradientSums {
  Mat3 velocity = Mat3::Zero();  // sum_j V_j (v_j - v_i) (x) grad W
  Mat3 moment = Mat3::Zero();    // sum_j V_j (x_j - x_i) (x) grad W
};

// A wall neighbour enters with its no-slip ghost velocity.
const Vec3& neighbour_velocity(std::size_t j, const Fields& f) {
  return is_fluid(f.kind[j]) ? f.velocity[j] : f.wall_velocity[j];
}

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
    sums.velocity += volume * (neighbour_velocity(j, f) - v_i) * grad.transpose();
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

Mat3 velocity_gradient(std::size_t i, const Fields& fields, const CellGrid& grid,
                       const KernelTable& gradient_kernel, int dimensions, bool corrected) {
  const GradientSums sums = gradient_sums(i, fields, grid, gradient_kernel);
  return corrected ? Mat3(sums.velocity * correction(sums.moment, dimensions)) : sums.velocity;
}

}  // namespace partimix::sph
