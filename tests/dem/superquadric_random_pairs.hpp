#pragma once
// Random pairs of superquadric grains for tests/dem/superquadric_contact_test.cpp: half-axes in
// [0.5, 2], blockiness n1, n2 in {2, 3, 4, 6, 8, 10} (a quarter of the grains ellipsoids, or a
// chosen share),
// uniformly random orientations and direction between the centres, and a chosen gap along the
// centre line from the distance at which the grains would just touch (by the brute-force
// reference of superquadric_reference.hpp).
#include <array>
#include <memory>
#include <random>

#include "dem/random_orientation.hpp"
#include "dem/superquadric.hpp"
#include "dem/superquadric_contact.hpp"
#include "superquadric_reference.hpp"

namespace partimix::dem::reference {

struct RandomPair {
  std::unique_ptr<Superquadric> shape_i;
  std::unique_ptr<Superquadric> shape_j;
  GrainPose i;
  GrainPose j;
  double length;    // the smallest half-axis of the two grains
  Midway midway;    // the reference midway point (scale < 1: touching)
  double touching;  // the centre distance at which the grains would just touch
};

class PairMaker {
 public:
  // `ellipsoids`: the share of ellipsoids among the grains.
  explicit PairMaker(unsigned seed, double ellipsoids = 0.25)
      : random_(seed), ellipsoids_(ellipsoids) {}

  // Centre distance touching + gap * length along a random direction.
  RandomPair make(double gap) {
    RandomPair pair;
    pair.shape_i = shape();
    pair.shape_j = shape();
    pair.length =
        std::min(pair.shape_i->half_axes().minCoeff(), pair.shape_j->half_axes().minCoeff());
    const Vec3 centre(uniform(-5.0, 5.0), uniform(-5.0, 5.0), uniform(-5.0, 5.0));
    const Vec3 u = unit();
    pair.i = {pair.shape_i.get(), centre, rotation()};
    pair.j = {pair.shape_j.get(), centre + u, rotation()};
    const Vec3 normal = midway_normal(pair.i, pair.j);
    pair.touching = 1.0 / midway(pair.i, pair.j, normal).scale;
    pair.j.centre = centre + (pair.touching + gap * pair.length) * u;
    pair.midway = midway(pair.i, pair.j, normal);
    return pair;
  }

  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(random_); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

 private:
  std::unique_ptr<Superquadric> shape() {
    const Vec3 axes(uniform(0.5, 2.0), uniform(0.5, 2.0), uniform(0.5, 2.0));
    if (uniform(0.0, 1.0) < ellipsoids_)
      return std::make_unique<Superquadric>(axes, 2.0, 2.0);
    constexpr std::array<double, 6> kBlockiness{2.0, 3.0, 4.0, 6.0, 8.0, 10.0};
    std::uniform_int_distribution<std::size_t> pick(0, kBlockiness.size() - 1);
    return std::make_unique<Superquadric>(axes, kBlockiness[pick(random_)],
                                          kBlockiness[pick(random_)]);
  }

  Vec3 unit() {
    std::normal_distribution<> gauss;
    return Vec3(gauss(random_), gauss(random_), gauss(random_)).normalized();
  }

  Mat3 rotation() { return testing::random_orientation(random_).toRotationMatrix(); }

  std::mt19937 random_;
  double ellipsoids_;
};

}  // namespace partimix::dem::reference
