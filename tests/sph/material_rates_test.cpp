// The multi-material scheme's velocity gradient (docs/multi-material-sph.md, "Solid";
// sph/multi_material/material_rates.hpp): corrected to first order by B^-1, it is exact for a
// linear velocity field at every particle of a jittered 2D patch with free edges, corners
// included, where the plain SPH sum misses the truncated kernel's share (there it is half or less
// of the true gradient, so the test fails without the correction).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "particles/cell_grid.hpp"
#include "sph/kernel.hpp"
#include "sph/multi_material/material_rates.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 1e-3;
constexpr int kSide = 12;

class JitteredPatch : public ::testing::Test {
 protected:
  void SetUp() override {
    domain.dimensions = 2;
    domain.lo = Vec3(-kSpacing, -kSpacing, 0.0);
    domain.hi = Vec3((kSide + 1) * kSpacing, (kSide + 1) * kSpacing, 0.0);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.15 * kSpacing, 0.15 * kSpacing);
    gradient << 2.0, -1.0, 0.0, 0.5, 3.0, 0.0, 0.0, 0.0, 0.0;
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i) {
        const Vec3 x((i + 0.5) * kSpacing + jitter(random), (j + 0.5) * kSpacing + jitter(random),
                     0.0);
        position.push_back(x);
        velocity.push_back(gradient * x + Vec3(0.3, -0.2, 0.0));
      }
  }

  // The rates of every particle, all of one material at rest in pressure and stress.
  void evaluate() {
    const std::size_t n = position.size();
    const double h = 1.5 * kSpacing;
    const std::unique_ptr<Kernel> kernel = kernel_registry().create("wendland_c2");
    const ScaledKernel scaled(*kernel, 2);
    CellGrid grid(domain, scaled.support() * h);
    grid.build(position);
    const std::vector<double> mass(n, 1000.0 * kSpacing * kSpacing), lengths(n, h),
        density(n, 1000.0), omega(n, 1.0), zero(n, 0.0), spacing(n, kSpacing), sound_speed(n, 10.0);
    const std::vector<Mat3> stress(n, Mat3::Zero());
    const MaterialParticles particles{position, velocity, mass,   lengths, density,     omega,
                                      zero,     stress,   stress, spacing, sound_speed, zero};
    acceleration.assign(n, Vec3::Zero());
    expansion.assign(n, 0.0);
    heating.assign(n, 0.0);
    velocity_gradient.assign(n, Mat3::Zero());
    unity_gradient.assign(n, Vec3::Zero());
    material_rates(particles, n, grid, scaled, DensityPairing::continuity, ArtificialViscosity{},
                   {acceleration, expansion, heating, velocity_gradient, unity_gradient});
  }

  Domain domain;
  Mat3 gradient;
  std::vector<Vec3> position, velocity, acceleration, unity_gradient;
  std::vector<double> expansion, heating;
  std::vector<Mat3> velocity_gradient;
};

TEST_F(JitteredPatch, VelocityGradientIsExactForALinearField) {
  evaluate();
  for (std::size_t i = 0; i < position.size(); ++i)
    EXPECT_LT((velocity_gradient[i] - gradient).norm(), 1e-9 * gradient.norm()) << "particle " << i;
}

}  // namespace
}  // namespace partimix::sph
