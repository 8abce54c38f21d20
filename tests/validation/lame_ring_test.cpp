// A thick elastic ring under internal pressure on the multi-material scheme (Lamé;
// docs/multi-material-sph.md, "Validation"): a 2D ring (plane strain) of inner radius a = 1 cm
// and outer radius b = 2 cm, G = 1 MPa, K = 2.5 MPa, laid as 10 rings of particles 1 mm apart,
// holds a viscous liquid that starts compressed to about 10 kPa; the ring expands, the liquid's
// viscosity damps the breathing, and the ring's hoop stress settles on Lamé's
//   sigma_theta(r) = p_i a^2 / (b^2 - a^2) (1 + b^2 / r^2),
// with p_i the liquid's pressure, whatever the elastic constants. Averaged over the last quarter
// of 50 ms: the ring's hoop load, the sum of its layers' mean hoop stress times their spacing,
// equals p_i a (a half ring's balance; held to 3%), and the hoop stress of each pair of adjacent
// layers but the outer two (the rings of the polar lattice alternate by a few percent) lies
// within 5% of p_i of Lamé at their mean radius. The breathing that the start's step of
// pressure sets off falls to about a fifth of itself each period of 11.6 ms; over the last quarter
// of 40 ms its remnant still moved the total Lagrangian ring's pairs by up to 1% of p_i (+5.2%
// where 80 ms gave +4.4%). Measured (2026-12-01): load +2.0%, pairs +2.2, +2.6, +2.1, +2.1% of p_i
// (at 40 ms: +2.6%, pairs +4.0 to +2.4%; before the velocity gradient's correction: load
// +2.0%, pairs +6.2 to +4.0%, the outermost layer -17%). Without the artificial stress: with
// Monaghan's (epsilon = 0.3) the hoop stress comes out 10-30% of p_i high and the load +15%, as
// its repulsion of particles under tension carries a share of a static load. The same ring as a
// total Lagrangian solid (docs/multi-material-sph.md, "Total Lagrangian solids"; hourglass 0.1;
// its density from det F), same tolerances: load +2.1%, pairs -0.5, +4.2, +3.3, +3.0% of p_i
// (with the hourglass at 1, at 40 ms: -6.6 to +6.7%; with B^-1 in its momentum, the inner pair
// -67%).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "particles/particle_store.hpp"
#include "sph/multi_material/multi_material_solver.hpp"
#include "support/elastic_solid.hpp"
#include "support/multi_material_setup.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 1e-3;
constexpr double kInner = 0.01;
constexpr double kOuter = 0.02;
constexpr int kLayers = 10;

// Without the artificial stress: its repulsion takes a share of a static load (see above).
MaterialSpec ring_solid(bool total_lagrangian) {
  MaterialSpec spec = test_support::elastic_solid("ring", 1000.0, 2.5e6, 1.0e6, 0.0);
  spec.solid->total_lagrangian = total_lagrangian;
  return spec;
}

MaterialSpec pressurised_liquid() {
  MaterialSpec spec;
  spec.name = "liquid";
  spec.eos.model = "tait";
  spec.eos.reference_density = 1000.0;
  spec.eos.sound_speed = 30.0;
  spec.eos.gamma = 1.0;
  spec.density = 1000.0 * (1.0 + 1.0e4 / (1000.0 * 30.0 * 30.0));
  spec.specific_heat = 1000.0;
  spec.viscosity = 2.0;
  return spec;
}

// Particles on rings of radius (k + 1/2) dp about the origin, from ring `first` to `last`.
void lay_rings(ParticleStore& store, std::vector<std::int32_t>& material, int first, int last,
               int index, double density) {
  for (int k = first; k < last; ++k) {
    const double r = (k + 0.5) * kSpacing;
    const int count =
        std::max(1, static_cast<int>(std::lround(2.0 * std::numbers::pi * r / kSpacing)));
    for (int n = 0; n < count; ++n) {
      const double angle = 2.0 * std::numbers::pi * (n + 0.5 * (k % 2)) / count;
      const std::size_t i = store.size();
      store.resize(i + 1);
      store.position()[i] = r * Vec3(std::cos(angle), std::sin(angle), 0.0);
      store.mass()[i] = density * kSpacing * kSpacing;
      store.id()[i] = static_cast<std::int64_t>(i);
      material.push_back(index);
    }
  }
}

class LameRing : public ::testing::TestWithParam<bool> {};

TEST_P(LameRing, HoopStressFollowsLame) {
  const Domain domain = test_support::plane_domain(-0.03, -0.03, 0.03, 0.03);
  const Config config =
      test_support::multi_material_config(kSpacing, {ring_solid(GetParam()), pressurised_liquid()});
  ParticleStore store;
  std::vector<std::int32_t> material;
  const int inner_rings = static_cast<int>(std::lround(kInner / kSpacing));
  lay_rings(store, material, 0, inner_rings, 1, *pressurised_liquid().density);
  lay_rings(store, material, inner_rings, inner_rings + kLayers, 0, 1000.0);
  store.add_integer("material", "").values = material;
  MultiMaterialSolver solver(store, domain, config, Vec3::Zero());
  const std::vector<double>& pressure = store.find_scalar("pressure")->values;
  const std::vector<Vec3>& normal = store.find_vector("deviatoric_stress_normal")->values;
  const std::vector<Vec3>& shear = store.find_vector("deviatoric_stress_shear")->values;
  const double duration = 0.05;
  std::vector<double> hoop(kLayers, 0.0), radius(kLayers, 0.0);
  std::vector<int> count(kLayers, 0);
  double liquid_pressure = 0.0;
  int liquid_samples = 0;
  while (solver.time() < duration) {
    solver.step(solver.stable_dt());
    if (solver.time() < 0.75 * duration)
      continue;
    for (std::size_t i = 0; i < store.size(); ++i) {
      const Vec3& x = store.position()[i];
      if (material[i] == 1) {
        liquid_pressure += pressure[i];
        ++liquid_samples;
        continue;
      }
      const int layer = static_cast<int>(std::floor(x.norm() / kSpacing)) - inner_rings;
      if (layer < 0 || layer >= kLayers)
        continue;
      const Vec3 t = Vec3(-x.y(), x.x(), 0.0).normalized();
      const double s_tt = normal[i].x() * t.x() * t.x() + normal[i].y() * t.y() * t.y() +
                          2.0 * shear[i].x() * t.x() * t.y();
      hoop[layer] += s_tt - pressure[i];
      radius[layer] += x.norm();
      ++count[layer];
    }
  }
  const double p_inner = liquid_pressure / liquid_samples;
  const double a2 = kInner * kInner, b2 = kOuter * kOuter;
  std::printf("liquid pressure %.4g Pa\n", p_inner);
  std::vector<double> mean_hoop(kLayers), mean_radius(kLayers);
  double load = 0.0;
  for (int layer = 0; layer < kLayers; ++layer) {
    mean_hoop[layer] = hoop[layer] / count[layer];
    mean_radius[layer] = radius[layer] / count[layer];
    load += mean_hoop[layer] * kSpacing;
  }
  std::printf("hoop load %.4g N/m against p_i a = %.4g N/m\n", load, p_inner * kInner);
  EXPECT_NEAR(load, p_inner * kInner, 0.03 * p_inner * kInner);
  for (int pair = 0; pair + 1 < kLayers - 2; pair += 2) {
    const double measured = 0.5 * (mean_hoop[pair] + mean_hoop[pair + 1]);
    const double r = 0.5 * (mean_radius[pair] + mean_radius[pair + 1]);
    const double lame = p_inner * a2 / (b2 - a2) * (1.0 + b2 / (r * r));
    std::printf("r %.4f mm: hoop %.4g Pa, Lame %.4g Pa (%+.1f%% of p_i)\n", r * 1e3, measured, lame,
                100.0 * (measured - lame) / p_inner);
    EXPECT_NEAR(measured, lame, 0.05 * p_inner) << "layers " << pair << ", " << pair + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(Formulations, LameRing, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return param.param ? "TotalLagrangian" : "UpdatedLagrangian";
                         });

}  // namespace
}  // namespace partimix::sph
