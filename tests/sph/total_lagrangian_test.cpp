// Total Lagrangian solids (docs/multi-material-sph.md, "Total Lagrangian solids";
// sph/multi_material/total_lagrangian.hpp) on a 2D patch of 12 x 12 particles with free edges,
// its reference positions jittered by up to 0.15 spacings:
// - an affine map x = A X + c with velocity v = W x gives F = A and L = W at every particle,
//   edges and corners included (the first-order correction makes them exact: 1e-9);
// - on the unjittered lattice, a uniform stress under an affine map leaves the particles whose
//   whole support lies inside the patch unforced (the pair forces cancel: 1e-9 of one pair's),
//   and so does the hourglass penalty (its error vanishes for an affine map);
// - one particle moved off the affine map is pushed back by the hourglass penalty alone;
// - the pair forces are antisymmetric: the momentum of random stresses on a jittered, randomly
//   deformed patch sums to zero (1e-12 of the largest force).
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "sph/kernel.hpp"
#include "sph/multi_material/total_lagrangian.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 1e-3;
constexpr int kSide = 12;
constexpr double kH = 1.5 * kSpacing;

class Patch : public ::testing::Test {
 protected:
  void SetUp() override {
    domain.dimensions = 2;
    domain.lo = Vec3(-5.0 * kSpacing, -5.0 * kSpacing, 0.0);
    domain.hi = Vec3((kSide + 5) * kSpacing, (kSide + 5) * kSpacing, 0.0);
    map << 1.2, 0.1, 0.0, -0.05, 0.9, 0.0, 0.0, 0.0, 1.0;
    spin << 0.4, -1.0, 0.0, 2.0, -0.3, 0.0, 0.0, 0.0, 0.0;
  }

  // The reference lattice, jittered by up to `jitter` spacings, mapped by `map`.
  void lay(double jitter) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> offset(-jitter * kSpacing, jitter * kSpacing);
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i) {
        const Vec3 x0((i + 0.5) * kSpacing + offset(random), (j + 0.5) * kSpacing + offset(random),
                      0.0);
        reference.push_back(x0);
        position.push_back(map * x0 + Vec3(0.2, -0.1, 0.0) * kSpacing);
        velocity.push_back(spin * position.back());
      }
    const std::size_t n = reference.size();
    mass.assign(n, 1000.0 * kSpacing * kSpacing);
    volume.assign(n, kSpacing * kSpacing);
    h.assign(n, kH);
    bonded.assign(n, 1);
    stress.assign(n, Mat3::Zero());
    hourglass.assign(n, 0.0);
  }

  void evaluate() {
    const BondedParticles p{position, velocity, reference, mass,      volume,
                            h,        bonded,   stress,    hourglass, {}};
    TotalLagrangianSolids solids(domain, scaled, kH);
    acceleration.assign(position.size(), Vec3::Zero());
    solids.refer(p, position.size());
    solids.deform(p, position.size());
    solids.add_forces(p, position.size(), acceleration);
    deformation.assign(solids.deformation_gradient().begin(), solids.deformation_gradient().end());
    velocity_gradient.assign(solids.velocity_gradient().begin(), solids.velocity_gradient().end());
  }

  // Whether particle i's support in the reference lattice lies inside the patch.
  bool inside(std::size_t i) const {
    const double margin = scaled.support() * kH;
    const Vec3& x = reference[i];
    return x.x() > margin && x.y() > margin && x.x() < kSide * kSpacing - margin &&
           x.y() < kSide * kSpacing - margin;
  }

  std::unique_ptr<Kernel> kernel = kernel_registry().create("wendland_c2");
  ScaledKernel scaled{*kernel, 2};
  Domain domain;
  Mat3 map, spin;
  std::vector<Vec3> reference, position, velocity, acceleration;
  std::vector<double> mass, volume, h, hourglass;
  std::vector<std::uint8_t> bonded;
  std::vector<Mat3> stress, velocity_gradient, deformation;
};

TEST_F(Patch, AffineMapGivesItsDeformationAndVelocityGradients) {
  lay(0.15);
  evaluate();
  for (std::size_t i = 0; i < position.size(); ++i) {
    EXPECT_LT((deformation[i] - map).norm(), 1e-9) << "particle " << i;
    EXPECT_LT((velocity_gradient[i] - spin).norm(), 1e-9 * spin.norm()) << "particle " << i;
  }
}

TEST_F(Patch, UniformStressAndAffineMapLeaveTheInsideUnforced) {
  lay(0.0);
  Mat3 sigma;
  sigma << 3.0e5, 1.0e5, 0.0, 1.0e5, -2.0e5, 0.0, 0.0, 0.0, 0.5e5;
  stress.assign(position.size(), sigma);
  hourglass.assign(position.size(), 1.0e7);
  evaluate();
  // One pair's force over a particle's mass, the scale of the sums.
  const double scale = sigma.norm() * kSpacing * kSpacing / kH / (1000.0 * kSpacing * kSpacing);
  int checked = 0;
  for (std::size_t i = 0; i < position.size(); ++i) {
    if (!inside(i))
      continue;
    EXPECT_LT(acceleration[i].norm(), 1e-9 * scale) << "particle " << i;
    ++checked;
  }
  EXPECT_GE(checked, 16);
}

TEST_F(Patch, HourglassPenaltyPushesAStrayParticleBack) {
  lay(0.0);
  hourglass.assign(position.size(), 1.0e7);
  const std::size_t stray = kSide * (kSide / 2) + kSide / 2;
  const Vec3 off(0.2 * kSpacing, -0.1 * kSpacing, 0.0);
  position[stray] += off;
  evaluate();
  EXPECT_LT(acceleration[stray].dot(off), -0.5 * acceleration[stray].norm() * off.norm());
}

TEST_F(Patch, PairForcesKeepMomentum) {
  lay(0.15);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (std::size_t i = 0; i < position.size(); ++i) {
    position[i] += 0.1 * kSpacing * Vec3(unit(random), unit(random), 0.0);
    Mat3 s = Mat3::Zero();
    s(0, 0) = unit(random);
    s(1, 1) = unit(random);
    s(0, 1) = s(1, 0) = unit(random);
    stress[i] = 1.0e5 * s;
    hourglass[i] = 1.0e7 * (1.0 + unit(random));
  }
  evaluate();
  Vec3 momentum = Vec3::Zero();
  double largest = 0.0;
  for (std::size_t i = 0; i < position.size(); ++i) {
    momentum += mass[i] * acceleration[i];
    largest = std::max(largest, mass[i] * acceleration[i].norm());
  }
  EXPECT_LT(momentum.norm(), 1e-12 * largest);
}

}  // namespace
}  // namespace partimix::sph
