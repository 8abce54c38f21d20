#pragma once
// A uniformly random orientation from the test's own generator (four Gaussian components,
// normalised), so that a test's grains do not depend on the tests run before it in the same
// process, as Eigen's Quaterniond::UnitRandom (std::rand) made them.
#include <Eigen/Geometry>
#include <random>

namespace partimix::dem::testing {

inline Eigen::Quaterniond random_orientation(std::mt19937& random) {
  std::normal_distribution<double> gauss;
  return Eigen::Quaterniond(gauss(random), gauss(random), gauss(random), gauss(random))
      .normalized();
}

}  // namespace partimix::dem::testing
