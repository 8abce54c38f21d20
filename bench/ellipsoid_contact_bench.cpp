// The contact detection of two ellipsoids alone (dem/ellipsoid_contact.hpp), as the DEM solver
// calls it on a drum in steady rotation: touching pairs of the study drum's spheroids (sigma = 2,
// the volume of a 2 mm sphere, overlaps up to 2% of the short half-axis), each warm-started from
// its multiplier of the step before, after a step's motion (a translation of 3e-4 of the short
// half-axis and a turn of 3e-4 rad, 1.46 Newton evaluations per pair; the drum's solves
// average 1.23). The figure is the time per pair, which docs/performance.md weighs against the
// whole superquadric particle-step.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <optional>
#include <random>
#include <vector>

#include "dem/ellipsoid_contact.hpp"

namespace partimix::dem {
namespace {

struct WarmPair {
  Ellipsoid i;
  Ellipsoid j;
  double mu;
};

const Vec3 kHalfAxes = Vec3(1.5874e-3, 1.5874e-3, 3.1748e-3);

Mat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
      .normalized()
      .toRotationMatrix();
}

// Grain j along u from grain i at the distance where they just touch (bisection between the
// centres together and twice the sum of the long half-axes, surely apart), less an overlap.
Ellipsoid touching_partner(const Ellipsoid& i, const Vec3& u, const Mat3& rotation,
                           double overlap) {
  double lo = 0.0;
  double hi = 4.0 * kHalfAxes.maxCoeff();
  for (int n = 0; n < 60; ++n) {
    const double mid = 0.5 * (lo + hi);
    const Ellipsoid j = make_ellipsoid(i.centre + mid * u, rotation, kHalfAxes);
    (find_ellipsoid_contact(i, j, std::nullopt).touching ? lo : hi) = mid;
  }
  return make_ellipsoid(i.centre + (lo - overlap) * u, rotation, kHalfAxes);
}

std::vector<WarmPair> warm_pairs(int count) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 0.02);
  std::vector<WarmPair> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    const Ellipsoid i = make_ellipsoid(Vec3::Zero(), random_rotation(rng), kHalfAxes);
    const Vec3 u = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const Mat3 rotation_j = random_rotation(rng);
    const Ellipsoid j = touching_partner(i, u, rotation_j, uniform(rng) * kHalfAxes.x());
    const SuperquadricContact before = find_ellipsoid_contact(i, j, std::nullopt);
    const Vec3 shift = 3e-4 * kHalfAxes.x() * Vec3(normal(rng), normal(rng), normal(rng));
    const Vec3 axis = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const Mat3 turn = Eigen::AngleAxisd(3e-4, axis).toRotationMatrix();
    const Ellipsoid moved = make_ellipsoid(j.centre + shift, turn * rotation_j, kHalfAxes);
    if (before.touching && find_ellipsoid_contact(i, moved, before.mu).touching)
      pairs.push_back({i, moved, before.mu});
  }
  return pairs;
}

void ellipsoid_contact_warm(benchmark::State& state) {
  const std::vector<WarmPair> pairs = warm_pairs(512);
  double iterations = 0.0;
  for (const WarmPair& p : pairs) {
    iterations += solve_ellipsoid_contact({p.i.centre, p.i.form, kHalfAxes.x()},
                                          {p.j.centre, p.j.form, kHalfAxes.x()}, p.mu)
                      .iterations;
  }
  for (auto _ : state) {
    for (const WarmPair& p : pairs) {
      const SuperquadricContact c = solve_ellipsoid_contact(
          {p.i.centre, p.i.form, kHalfAxes.x()}, {p.j.centre, p.j.form, kHalfAxes.x()}, p.mu);
      benchmark::DoNotOptimize(c);
    }
  }
  state.counters["iterations_per_pair"] = iterations / static_cast<double>(pairs.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
}

BENCHMARK(ellipsoid_contact_warm);

}  // namespace
}  // namespace partimix::dem
