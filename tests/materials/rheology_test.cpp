// Rheology models (docs/rheology.md): each viscosity curve against its formula, the limits at
// zero and infinite shear rate, the Papanastasiou regularisation against the plain model, and
// the bounds of BoundedRheology (never NaN, infinite model values clamped).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "materials/rheology.hpp"

namespace partimix::materials {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const std::vector<double> kShearRates{1.0e-6, 1.0e-3, 0.1, 1.0, 7.5, 1.0e2, 1.0e5};

double model_viscosity(const RheologyConfig& config, double shear_rate) {
  return rheology_registry().create(config.model, config)->apparent_viscosity(shear_rate);
}

// Checks the model against `formula` at kShearRates, to a relative 1e-12.
template <class Formula>
void expect_curve(const RheologyConfig& config, Formula formula) {
  for (const double rate : kShearRates) {
    const double expected = formula(rate);
    EXPECT_NEAR(model_viscosity(config, rate), expected, 1.0e-12 * expected)
        << config.model << " at shear rate " << rate;
  }
}

RheologyConfig power_law(double k, double n) {
  RheologyConfig c;
  c.model = "power_law";
  c.consistency = k;
  c.flow_index = n;
  return c;
}

RheologyConfig herschel_bulkley(double tau0, double k, double n, const std::string& reg) {
  RheologyConfig c = power_law(k, n);
  c.model = "herschel_bulkley";
  c.yield_stress = tau0;
  c.regularisation = reg;
  return c;
}

RheologyConfig bingham(double tau0, double mu_p, const std::string& reg) {
  RheologyConfig c;
  c.model = "bingham";
  c.yield_stress = tau0;
  c.plastic_viscosity = mu_p;
  c.regularisation = reg;
  return c;
}

RheologyConfig cross(double eta0, double eta_inf, double lambda, double n) {
  RheologyConfig c;
  c.model = "cross";
  c.zero_shear_viscosity = eta0;
  c.infinite_shear_viscosity = eta_inf;
  c.time_constant = lambda;
  c.flow_index = n;
  return c;
}

RheologyConfig carreau(double eta0, double eta_inf, double lambda, double n, double a) {
  RheologyConfig c = cross(eta0, eta_inf, lambda, n);
  c.model = "carreau";
  c.yasuda_exponent = a;
  return c;
}

TEST(Rheology, EveryModelIsRegistered) {
  for (const std::string name :
       {"newtonian", "power_law", "herschel_bulkley", "bingham", "cross", "carreau"}) {
    EXPECT_TRUE(rheology_registry().contains(name)) << name;
  }
}

TEST(Rheology, NewtonianIsConstant) {
  RheologyConfig c;
  c.viscosity = 1.0e-3;
  expect_curve(c, [](double) { return 1.0e-3; });
  EXPECT_EQ(model_viscosity(c, 0.0), 1.0e-3);
}

TEST(Rheology, PowerLawFollowsKGammaDotToTheNMinusOne) {
  // The CMC solution of the seed (K = 13.9 Pa s^n, n = 0.47) and a shear-thickening fluid.
  expect_curve(power_law(13.9, 0.47), [](double g) { return 13.9 * std::pow(g, -0.53); });
  expect_curve(power_law(0.2, 1.5), [](double g) { return 0.2 * std::sqrt(g); });
}

TEST(Rheology, PowerLawAtRestIsInfiniteZeroOrK) {
  EXPECT_EQ(model_viscosity(power_law(13.9, 0.47), 0.0), kInfinity);
  EXPECT_EQ(model_viscosity(power_law(2.0, 1.0), 0.0), 2.0);
  EXPECT_EQ(model_viscosity(power_law(0.2, 1.5), 0.0), 0.0);
}

TEST(Rheology, PowerLawAtVeryLargeShearRate) {
  EXPECT_NEAR(model_viscosity(power_law(13.9, 0.47), 1.0e12), 13.9 * std::pow(1.0e12, -0.53),
              1.0e-20);
  EXPECT_EQ(model_viscosity(power_law(13.9, 0.47), kInfinity), 0.0);
  EXPECT_EQ(model_viscosity(power_law(0.2, 1.5), kInfinity), kInfinity);
}

TEST(Rheology, HerschelBulkleyBiviscousIsThePlainModel) {
  // The seed's eq. 4: tau = tau0 + K gd^n, so eta = tau0 / gd + K gd^(n-1).
  expect_curve(herschel_bulkley(5.0, 13.9, 0.47, "biviscous"),
               [](double g) { return 5.0 / g + 13.9 * std::pow(g, -0.53); });
  EXPECT_EQ(model_viscosity(herschel_bulkley(5.0, 2.0, 1.5, "biviscous"), 0.0), kInfinity);
}

TEST(Rheology, BinghamBiviscousIsThePlainModel) {
  expect_curve(bingham(5.0, 0.1, "biviscous"), [](double g) { return 5.0 / g + 0.1; });
  EXPECT_EQ(model_viscosity(bingham(5.0, 0.1, "biviscous"), 0.0), kInfinity);
}

TEST(Rheology, PapanastasiouFollowsItsFormula) {
  RheologyConfig c = herschel_bulkley(5.0, 13.9, 0.47, "papanastasiou");
  c.papanastasiou_exponent = 200.0;
  expect_curve(c, [](double g) {
    return 5.0 * (1.0 - std::exp(-200.0 * g)) / g + 13.9 * std::pow(g, -0.53);
  });
}

TEST(Rheology, PapanastasiouAtRestIsTau0TimesMPlusThePowerLawPart) {
  RheologyConfig c = bingham(5.0, 0.1, "papanastasiou");
  c.papanastasiou_exponent = 1000.0;
  EXPECT_DOUBLE_EQ(model_viscosity(c, 0.0), 5.0 * 1000.0 + 0.1);
  EXPECT_NEAR(model_viscosity(c, 1.0e-12), 5.0 * 1000.0 + 0.1, 1.0e-9 * 5000.0);
  EXPECT_DOUBLE_EQ(model_viscosity(herschel_bulkley(5.0, 2.0, 1.0, "papanastasiou"), 0.0),
                   5.0 * 1000.0 + 2.0);
  EXPECT_DOUBLE_EQ(model_viscosity(herschel_bulkley(5.0, 2.0, 1.5, "papanastasiou"), 0.0),
                   5.0 * 1000.0);
  EXPECT_EQ(model_viscosity(herschel_bulkley(5.0, 2.0, 0.5, "papanastasiou"), 0.0), kInfinity);
}

TEST(Rheology, PapanastasiouApproachesThePlainModelAtLargeShearRate) {
  for (const double rate : {0.1, 1.0, 100.0}) {
    const double plain = model_viscosity(herschel_bulkley(5.0, 13.9, 0.47, "biviscous"), rate);
    const double regularised =
        model_viscosity(herschel_bulkley(5.0, 13.9, 0.47, "papanastasiou"), rate);
    EXPECT_NEAR(regularised, plain, 1.0e-12 * plain) << rate;  // exp(-m gd) <= exp(-100)
  }
}

TEST(Rheology, ZeroYieldStressLeavesThePowerLaw) {
  for (const std::string reg : {"papanastasiou", "biviscous"}) {
    EXPECT_EQ(model_viscosity(herschel_bulkley(0.0, 2.0, 1.0, reg), 0.0), 2.0) << reg;
    EXPECT_EQ(model_viscosity(bingham(0.0, 0.1, reg), 0.0), 0.1) << reg;
  }
}

TEST(Rheology, CrossFollowsItsFormula) {
  expect_curve(cross(10.0, 0.01, 0.5, 0.8),
               [](double g) { return 0.01 + (10.0 - 0.01) / (1.0 + std::pow(0.5 * g, 0.8)); });
}

TEST(Rheology, CarreauYasudaFollowsItsFormula) {
  expect_curve(carreau(10.0, 0.01, 0.5, 0.4, 1.5), [](double g) {
    return 0.01 + (10.0 - 0.01) * std::pow(1.0 + std::pow(0.5 * g, 1.5), (0.4 - 1.0) / 1.5);
  });
  // a = 2: the Carreau model, eta_inf + (eta0 - eta_inf) (1 + (lambda gd)^2)^((n-1)/2).
  expect_curve(carreau(10.0, 0.0, 0.5, 0.4, 2.0),
               [](double g) { return 10.0 * std::pow(1.0 + 0.25 * g * g, -0.3); });
}

TEST(Rheology, CrossAndCarreauRunFromEta0ToEtaInf) {
  for (const RheologyConfig& c :
       {cross(10.0, 0.01, 0.5, 0.8), carreau(10.0, 0.01, 0.5, 0.4, 2.0)}) {
    EXPECT_EQ(model_viscosity(c, 0.0), 10.0) << c.model;
    EXPECT_NEAR(model_viscosity(c, 1.0e-9), 10.0, 1.0e-6) << c.model;
    EXPECT_NEAR(model_viscosity(c, 1.0e15), 0.01, 1.0e-4) << c.model;
    EXPECT_EQ(model_viscosity(c, kInfinity), 0.01) << c.model;
  }
}

TEST(RheologyBounds, ClampsToTheBounds) {
  RheologyConfig c = power_law(1.0, 0.5);
  c.viscosity_min = 0.01;
  c.viscosity_max = 100.0;
  const BoundedRheology rheology(c);
  EXPECT_EQ(rheology.viscosity(0.0), 100.0);
  EXPECT_EQ(rheology.viscosity(1.0e-8), 100.0);
  EXPECT_DOUBLE_EQ(rheology.viscosity(4.0), 0.5);
  EXPECT_EQ(rheology.viscosity(1.0e8), 0.01);
}

TEST(RheologyBounds, CapsTheBiviscousYieldStress) {
  RheologyConfig c = bingham(5.0, 0.1, "biviscous");
  c.viscosity_max = 1.0e3;
  const BoundedRheology rheology(c);
  EXPECT_EQ(rheology.viscosity(0.0), 1.0e3);
  EXPECT_DOUBLE_EQ(rheology.viscosity(1.0), 5.1);
}

TEST(RheologyBounds, NeverNaNAtRestOrExtremeShearRates) {
  std::vector<RheologyConfig> configs{power_law(13.9, 0.47),
                                      power_law(0.2, 1.5),
                                      herschel_bulkley(5.0, 13.9, 0.47, "papanastasiou"),
                                      herschel_bulkley(5.0, 13.9, 0.47, "biviscous"),
                                      bingham(5.0, 0.1, "papanastasiou"),
                                      bingham(5.0, 0.1, "biviscous"),
                                      cross(10.0, 0.0, 0.5, 0.8),
                                      carreau(10.0, 0.0, 0.5, 1.5, 2.0)};
  for (RheologyConfig& c : configs) {
    c.viscosity_min = 1.0e-4;
    c.viscosity_max = 1.0e4;
    const BoundedRheology rheology(c);
    for (const double rate : {0.0, std::numeric_limits<double>::denorm_min(), 1.0e300, kInfinity}) {
      const double eta = rheology.viscosity(rate);
      EXPECT_FALSE(std::isnan(eta)) << c.model << " at " << rate;
      EXPECT_GE(eta, 1.0e-4) << c.model << " at " << rate;
      EXPECT_LE(eta, 1.0e4) << c.model << " at " << rate;
    }
  }
}

TEST(RheologyBounds, RejectsAnUnknownModel) {
  RheologyConfig c;
  c.model = "maxwell";
  EXPECT_THROW(BoundedRheology{c}, std::invalid_argument);
}

TEST(RheologyBounds, RejectsAnUnknownRegularisation) {
  EXPECT_THROW(BoundedRheology{bingham(5.0, 0.1, "tanh")}, std::invalid_argument);
}

TEST(RheologyBounds, RejectsDisorderedBounds) {
  RheologyConfig c;
  c.viscosity = 1.0;
  c.viscosity_min = 2.0;
  c.viscosity_max = 1.0;
  EXPECT_THROW(BoundedRheology{c}, std::invalid_argument);
}

}  // namespace
}  // namespace partimix::materials
