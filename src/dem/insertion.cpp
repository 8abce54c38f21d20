#include "dem/insertion.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "dem/superquadric_contact.hpp"

namespace partimix::dem {

namespace {

// Spheres placed so far, hashed by cells of the largest diameter: a candidate meets only
// spheres in the 27 cells around its own.
class PlacedSpheres {
 public:
  explicit PlacedSpheres(double cell) : cell_(cell) {}

  // Whether a sphere at x overlaps a placed one that `touches(j)` confirms.
  template <class Touches>
  bool overlaps(const Vec3& x, double radius, const Grains& grains, Touches&& touches) const {
    const auto c = cell_of(x);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (found == cells_.end())
            continue;
          for (const std::size_t j : found->second) {
            const double reach = radius + grains.radius[j];
            if ((grains.position[j] - x).squaredNorm() < reach * reach && touches(j))
              return true;
          }
        }
    return false;
  }

  void add(const Vec3& x, std::size_t index) {
    const auto c = cell_of(x);
    cells_[key(c[0], c[1], c[2])].push_back(index);
  }

 private:
  std::array<long, 3> cell_of(const Vec3& x) const {
    return {std::lround(std::floor(x.x() / cell_)), std::lround(std::floor(x.y() / cell_)),
            std::lround(std::floor(x.z() / cell_))};
  }
  static std::uint64_t key(long x, long y, long z) {
    const auto part = [](long v) { return static_cast<std::uint64_t>(v + (1L << 20)) & 0x1FFFFF; };
    return part(x) << 42 | part(y) << 21 | part(z);
  }

  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// A rotation uniform over all rotations: a normalised Gaussian 4-vector as a quaternion.
Eigen::Quaterniond random_turn(std::mt19937_64& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Vector4d q(normal(random), normal(random), normal(random), normal(random));
  return Eigen::Quaterniond(q.normalized());
}

// The region's outward direction at x: the gradient of its signed distance (central
// differences of step h), zero where it has none.
Vec3 outward(const geometry::Shape& region, const Vec3& x, double h) {
  Vec3 gradient;
  for (int k = 0; k < 3; ++k) {
    gradient[k] = region.signed_distance(x + h * Vec3::Unit(k)) -
                  region.signed_distance(x - h * Vec3::Unit(k));
  }
  return gradient;
}

// The largest signed distance to the region over a convex grain's surface, climbed from the
// support point along d: each step takes the support point along the region's outward direction
// at the last one, which for a convex region (a convex signed distance) never lowers the
// distance (a conditional-gradient step, docs/dem.md, "Filling"); it stops when the point moves
// by less than 1e-10 of the grain's radius.
double farthest_outside(const geometry::Shape& region, const Vec3& x, double radius,
                        const Superquadric& shape, const Mat3& turn, Vec3 d) {
  constexpr int kMostSteps = 50;
  const double h = 1e-3 * radius;
  Vec3 point = x + turn * shape.support(turn.transpose() * d);
  double distance = region.signed_distance(point);
  for (int step = 0; step < kMostSteps; ++step) {
    d = outward(region, point, h);
    if (d.squaredNorm() == 0.0)
      break;
    const Vec3 next = x + turn * shape.support(turn.transpose() * d);
    const double next_distance = region.signed_distance(next);
    const bool settled = (next - point).norm() < 1e-10 * radius;
    if (next_distance > distance) {
      point = next;
      distance = next_distance;
    }
    if (settled || next_distance <= distance - 1e-12 * radius)
      break;
  }
  return distance;
}

// Whether a candidate lies inside the region: a sphere wholly; a superquadric when its bounding
// sphere does, or else when its surface's largest signed distance, climbed from its farthest
// points along the six axes and along the region's outward direction at its centre, is not
// positive.
bool inside(const geometry::Shape& region, const Vec3& x, double radius,
            const std::optional<Superquadric>& shape, const Mat3& turn) {
  const double centre_distance = region.signed_distance(x);
  if (centre_distance <= -radius)
    return true;
  if (!shape)
    return false;
  for (const Vec3& d :
       {Vec3(Vec3::UnitX()), Vec3(-Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(-Vec3::UnitY()),
        Vec3(Vec3::UnitZ()), Vec3(-Vec3::UnitZ()), outward(region, x, 1e-3 * radius)}) {
    if (d.squaredNorm() > 0.0 && farthest_outside(region, x, radius, *shape, turn, d) > 0.0)
      return false;
  }
  return true;
}

// Refuses a count whose spheres, at the smallest radius, could not fit in the region's bounding
// box even at the densest packing of equal spheres (pi / sqrt(18)): no candidate is drawn then.
void check_capacity(const geometry::Shape& region, const InsertionRequest& request) {
  const Vec3 size = region.upper() - region.lower();
  const double box = size.x() * size.y() * size.z();
  const double each = request.shape
                          ? request.shape->volume()
                          : 4.0 / 3.0 * std::numbers::pi * std::pow(request.radius_min, 3);
  const double spheres = request.count * each;
  const double densest = request.shape ? 1.0 : std::numbers::pi / std::sqrt(18.0);
  if (std::isfinite(box) && spheres > densest * box) {
    throw std::runtime_error(fmt::format(
        "{} spheres of radius {:.3g} m take {:.3g} m^3, more than the region's bounding box "
        "holds at the densest packing ({:.3g} x {:.3g} m^3); make the region larger or the "
        "count smaller",
        request.count, request.radius_min, spheres, densest, box));
  }
}

}  // namespace

Grains insert_random(const geometry::Shape& region, const InsertionRequest& request) {
  check_capacity(region, request);
  std::mt19937_64 random(request.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 lo = region.lower();
  const Vec3 size = region.upper() - lo;
  Grains grains;
  PlacedSpheres placed(2.0 * request.radius_max);
  long attempts = 0;
  for (int failures = 0; failures < request.attempts_per_grain &&
                         static_cast<int>(grains.position.size()) < request.count;) {
    ++attempts;
    const double radius =
        request.radius_min + (request.radius_max - request.radius_min) * unit(random);
    const Vec3 x = lo + Vec3(unit(random), unit(random), unit(random)).cwiseProduct(size);
    const Eigen::Quaterniond turn = request.shape ? random_turn(random) : Eigen::Quaterniond();
    // Shapes touch when the midway point says so (or it cannot say: refused to be safe).
    auto touches = [&](std::size_t j) {
      if (!request.shape)
        return true;
      const SuperquadricContact contact = find_contact(
          {&*request.shape, x, turn.toRotationMatrix()},
          {&*request.shape, grains.position[j], grains.orientation[j].toRotationMatrix()},
          std::nullopt);
      return contact.touching || !contact.converged;
    };
    if (!inside(region, x, radius, request.shape, turn.toRotationMatrix()) ||
        placed.overlaps(x, radius, grains, touches)) {
      ++failures;
      continue;
    }
    failures = 0;
    placed.add(x, grains.position.size());
    grains.position.push_back(x);
    grains.radius.push_back(radius);
    grains.species.push_back(request.species);
    if (request.shape)
      grains.orientation.push_back(turn);
  }
  if (static_cast<int>(grains.position.size()) < request.count) {
    throw std::runtime_error(fmt::format(
        "only {} of {} grains fitted into the region without overlap ({} candidates in a row "
        "failed, {} in all); make the region larger, the count smaller or attempts larger",
        grains.position.size(), request.count, request.attempts_per_grain, attempts));
  }
  return grains;
}

}  // namespace partimix::dem
