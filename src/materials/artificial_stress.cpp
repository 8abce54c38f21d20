#include "materials/artificial_stress.hpp"

#include <Eigen/Eigenvalues>

namespace partimix::materials {

Mat3 artificial_stress(const Mat3& stress, double density, double epsilon) {
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(stress);
  Vec3 diagonal = Vec3::Zero();
  for (int a = 0; a < 3; ++a) {
    const double value = principal.eigenvalues()[a];
    if (value > 0.0)
      diagonal[a] = -epsilon * value / (density * density);
  }
  const Mat3& axes = principal.eigenvectors();
  return axes * diagonal.asDiagonal() * axes.transpose();
}

}  // namespace partimix::materials
