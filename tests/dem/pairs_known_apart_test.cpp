// Pairs known apart (docs/dem.md, "Pairs known apart"): a pair found apart with a gap g need not
// be looked at until its grains have travelled g between them.
// - The gaps find_ellipsoid_contact reports for apart ellipsoids (bounding spheres, centre line,
//   the contact function F > 1) never exceed the distance between the surfaces (the brute-force
//   support-function reference), on 2,000 random pairs from just apart to far apart, and are not
//   vacuous: their mean is at least half the true distance (measured 0.65).
// - A turn from q to q' moves no point within R of the centre by more than 2 R |q' - q|, the
//   rotational part of a grain's travel.
// - Skipping changes nothing: a bed of 144 falling, colliding ellipsoids and 72 spheres ends bit
//   for bit the same after 4,000 steps with lists that live long (a skin of 2 largest radii) as
//   when its solver is saved and restored every step, each restored list starting with no pair
//   known apart, so that every listed pair is looked at every step. Gaps taken 10% too large
//   break it (0.1% too large does not: few skips end that close to a contact).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <deque>
#include <memory>
#include <random>
#include <vector>

#include "core/state_archive.hpp"
#include "dem/dem_setups.hpp"
#include "dem/dem_solver.hpp"
#include "dem/ellipsoid_contact.hpp"
#include "dem/random_orientation.hpp"
#include "superquadric_random_pairs.hpp"

namespace partimix::dem {
namespace {

TEST(PairsKnownApart, EllipsoidGapsNeverExceedTheDistance) {
  reference::PairMaker maker(17, 1.0);
  double ratio_sum = 0.0;
  int apart = 0;
  for (int n = 0; n < 2000; ++n) {
    const double gap = maker.log_uniform(1e-3, 3.0);
    const reference::RandomPair pair = maker.make(gap);
    const SuperquadricContact c = find_ellipsoid_contact(
        make_ellipsoid(pair.i.centre, pair.i.rotation, pair.i.shape->half_axes()),
        make_ellipsoid(pair.j.centre, pair.j.rotation, pair.j.shape->half_axes()), std::nullopt);
    ASSERT_FALSE(c.touching) << "pair " << n;
    const double distance = -reference::penetration(pair.i, pair.j).depth;
    ASSERT_GT(distance, 0.0);
    EXPECT_LE(c.gap, distance * (1.0 + 1e-9)) << "pair " << n << ", gap " << gap;
    EXPECT_GE(c.gap, 0.0);
    ratio_sum += c.gap / distance;
    ++apart;
  }
  RecordProperty("mean_gap_over_distance", std::to_string(ratio_sum / apart));
  EXPECT_GT(ratio_sum / apart, 0.5);
}

TEST(PairsKnownApart, ATurnMovesNoPointFartherThanTwiceTheRadiusTimesTheQuaternionStep) {
  std::mt19937 random(5);
  std::normal_distribution<double> gauss;
  for (int n = 0; n < 10000; ++n) {
    const Eigen::Quaterniond q = testing::random_orientation(random);
    const double angle = 0.3 * std::abs(gauss(random));
    const Vec3 axis = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
    const Eigen::Quaterniond turned = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)) * q;
    const Vec3 p = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
    const double moved = (turned * p - q * p).norm();
    EXPECT_LE(moved, 2.0 * (turned.coeffs() - q.coeffs()).norm() * (1.0 + 1e-12));
  }
}

// 216 grains on a lattice in a closed box, every third a sphere, the rest prolate ellipsoids at
// random orientations, thrown at random and falling, for `steps` steps; every `restart` steps
// (0: never) the solver is saved and a new one restored from it, whose pair list starts afresh
// with no pair known apart (the solver's state is otherwise the same to the last bit: its
// checkpoints resume bit for bit).
struct Bed {
  Config config;
  Grains grains;
  Bed() {
    const Superquadric ellipsoid(Vec3(0.001, 0.001, 0.002), 2.0, 2.0);
    config.species = {Species{"ellipsoid", 2500.0, {1.0e7, 0.3}, ellipsoid},
                      Species{"sphere", 2500.0, {1.0e7, 0.3}, std::nullopt}};
    config.particle_interactions.assign(4, Interaction{0.5, 0.5, 0.01});
    config.wall_interactions.assign(2, Interaction{0.5, 0.5, 0.01});
    config.rolling_resistance = "constant_torque";
    config.neighbour_skin = 2.0;  // lists that live long
    for (int axis = 0; axis < 3; ++axis) {
      test::add_plane(config, -kHalf * Vec3::Unit(axis), Vec3::Unit(axis));
      test::add_plane(config, kHalf * Vec3::Unit(axis), -Vec3::Unit(axis));
    }
    std::mt19937 random(9);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 216; ++k) {
      grains.position.push_back(0.0042 * (Vec3(k % 6, k / 6 % 6, k / 36) - Vec3::Constant(2.5)));
      grains.species.push_back(k % 3 == 0 ? 1 : 0);
      grains.radius.push_back(0.0015);
      grains.velocity.push_back(0.5 * Vec3(unit(random), unit(random), unit(random)));
      grains.angular_velocity.push_back(100.0 * Vec3(unit(random), unit(random), unit(random)));
      grains.orientation.push_back(
          Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random)).normalized());
    }
  }
  static constexpr double kHalf = 0.015;
};

std::vector<Vec3> bed_after(int steps, int restart) {
  const Bed bed;
  const Vec3 gravity(0.0, 0.0, -9.81);
  std::deque<ParticleStore> stores(1);  // each solver keeps a reference to its store
  auto solver = std::make_unique<DemSolver>(stores.back(), test::box(1.1 * Bed::kHalf), bed.config,
                                            gravity, bed.grains);
  for (int n = 1; n <= steps; ++n) {
    solver->step(solver->stable_dt());
    if (restart > 0 && n % restart == 0) {
      StateArchive archive;
      solver->save(archive, "dem/");
      stores.emplace_back();
      solver = std::make_unique<DemSolver>(stores.back(), test::box(1.1 * Bed::kHalf), bed.config,
                                           gravity, bed.grains);
      solver->restore(archive, "dem/");
    }
  }
  EXPECT_GT(solver->mean_contacts(), 0.5);
  const ParticleStore& store = stores.back();
  const auto& omega = store.find_vector("angular_velocity")->values;
  const auto& turn = store.find_vector("orientation_v")->values;
  std::vector<std::size_t> by_id(store.size());
  for (std::size_t i = 0; i < store.size(); ++i)
    by_id[static_cast<std::size_t>(store.id()[i])] = i;
  std::vector<Vec3> state;
  for (const std::size_t i : by_id)
    state.insert(state.end(), {store.position()[i], store.velocity()[i], omega[i], turn[i]});
  return state;
}

TEST(PairsKnownApart, SkippingThemChangesNothingToTheLastBit) {
  const std::vector<Vec3> through = bed_after(4000, 0);
  const std::vector<Vec3> restarted = bed_after(4000, 1);
  ASSERT_EQ(through.size(), restarted.size());
  for (std::size_t k = 0; k < through.size(); ++k)
    ASSERT_EQ(through[k], restarted[k]) << "entry " << k;
}

}  // namespace
}  // namespace partimix::dem
