// coupling/drag_law.hpp (docs/cfd-dem.md, "The forces on a grain"): each law against its
// formula at chosen states, the lone sphere's standard drag, and the limits that stay finite.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/drag_law.hpp"
#include "coupling/drag_laws/gidaspow.hpp"

namespace partimix::coupling {
namespace {

constexpr double kD = 1e-3;      // [m]
constexpr double kRho = 1000.0;  // [kg/m³]
constexpr double kMu = 1e-3;     // [Pa s]

double force_on_lone_sphere(const DragLaw& law, double slip) {
  const DragState s{1.0, slip, kD, kRho, kMu};
  return law.coefficient(s) * M_PI * kD * kD * kD / 6.0 * slip;
}

// At ε = 1 Gidaspow's law is the standard drag (1/2) C_d ρ (π d² / 4) u² with Schiller and
// Naumann's C_d, and Stokes' 3 π μ d u as the slip vanishes.
TEST(DragLaw, GidaspowGivesALoneSphereItsStandardDrag) {
  const auto law = drag_law_registry().create("gidaspow");
  for (const double re : {1e-6, 0.1, 1.0, 10.0, 100.0, 500.0, 2000.0}) {
    const double slip = re * kMu / (kRho * kD);
    const double cd = re < 1000.0 ? 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687)) : 0.44;
    const double standard = 0.5 * cd * kRho * M_PI * kD * kD / 4.0 * slip * slip;
    EXPECT_NEAR(force_on_lone_sphere(*law, slip), standard, 1e-12 * standard) << "Re " << re;
  }
  EXPECT_NEAR(law->coefficient({1.0, 0.0, kD, kRho, kMu}), 18.0 * kMu / (kD * kD), 1e-9);
}

TEST(DragLaw, GidaspowSwitchesFromErgunToWenYuAtAVoidFractionOf08) {
  const auto law = drag_law_registry().create("gidaspow");
  const DragState dense{0.6, 0.01, kD, kRho, kMu};
  const double ergun = 150.0 * 0.4 * kMu / (0.6 * kD * kD) + 1.75 * kRho * 0.01 / kD;
  EXPECT_NEAR(law->coefficient(dense), ergun, 1e-12 * ergun);
  const DragState dilute{0.9, 0.01, kD, kRho, kMu};
  const double re = 0.9 * kRho * 0.01 * kD / kMu;
  const double cd = 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687));
  const double wen_yu = 0.75 * cd * 0.9 * kRho * 0.01 / kD * std::pow(0.9, -2.65);
  EXPECT_NEAR(law->coefficient(dilute), wen_yu, 1e-12 * wen_yu);
}

// The blend follows Ergun in a packed bed and Wen and Yu in a dilute suspension (φ within 1% of
// 1 and 0 at ε = 0.4 and 0.95), and is continuous at ε = 0.8 where the switch jumps.
TEST(DragLaw, TheBlendJoinsTheTwoSmoothly) {
  const auto blend = drag_law_registry().create("gidaspow_blended");
  const DragState packed{0.4, 0.02, kD, kRho, kMu};
  EXPECT_NEAR(blend->coefficient(packed), ergun_coefficient(packed),
              0.01 * ergun_coefficient(packed));
  const DragState dilute{0.95, 0.02, kD, kRho, kMu};
  EXPECT_NEAR(blend->coefficient(dilute), wen_yu_coefficient(dilute),
              0.01 * wen_yu_coefficient(dilute));
  const DragState below{0.8 - 1e-9, 0.02, kD, kRho, kMu};
  const DragState above{0.8 + 1e-9, 0.02, kD, kRho, kMu};
  EXPECT_NEAR(blend->coefficient(below), blend->coefficient(above),
              1e-6 * blend->coefficient(above));
  EXPECT_NEAR(blend->coefficient(above),
              0.5 * (ergun_coefficient(above) + wen_yu_coefficient(above)),
              1e-6 * blend->coefficient(above));
}

// Di Felice at ε = 1 is Dallavalle's sphere drag, C_d = (0.63 + 4.8 / √Re)²; in a suspension
// it carries ε^(2 - χ) with χ from Re.
TEST(DragLaw, DiFeliceFollowsItsFormula) {
  const auto law = drag_law_registry().create("di_felice");
  const double slip = 0.05;
  const double re = kRho * slip * kD / kMu;
  const double cd = std::pow(0.63 + 4.8 / std::sqrt(re), 2.0);
  const double standard = 0.5 * cd * kRho * M_PI * kD * kD / 4.0 * slip * slip;
  EXPECT_NEAR(force_on_lone_sphere(*law, slip), standard, 1e-12 * standard);
  const double eps = 0.7;
  const double re_s = eps * re;
  const double cd_s = std::pow(0.63 + 4.8 / std::sqrt(re_s), 2.0);
  const double chi = 3.7 - 0.65 * std::exp(-std::pow(1.5 - std::log10(re_s), 2.0) / 2.0);
  const double force =
      0.5 * cd_s * kRho * M_PI * kD * kD / 4.0 * eps * eps * slip * slip * std::pow(eps, -chi);
  const double k = law->coefficient({eps, slip, kD, kRho, kMu});
  EXPECT_NEAR(k * M_PI * kD * kD * kD / 6.0 * slip, force, 1e-12 * force);
  // Zero slip: finite, Stokes-like 0.75 * 4.8² μ / d² ε^(1 - 3.7).
  EXPECT_NEAR(law->coefficient({eps, 0.0, kD, kRho, kMu}),
              0.75 * 23.04 * kMu / (kD * kD) * std::pow(eps, -2.7), 1e-9);
}

TEST(DragLaw, UnknownNamesGiveNothing) {
  EXPECT_EQ(drag_law_registry().create("stokes_only"), nullptr);
  EXPECT_EQ(drag_law_registry().names().size(), 3u);
}

}  // namespace
}  // namespace partimix::coupling
