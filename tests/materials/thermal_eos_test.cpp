// Thermal equations of state (docs/multi-material-sph.md, "Equations of state"): each model's
// pressure against its formula written out here, the derivatives against central differences,
// the Redlich-Kwong gas's ideal-gas limit and critical point, the adiabatic sound speed of the
// ideal gas, and the registry.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "materials/thermal_eos.hpp"
#include "materials/thermal_eos/tait.hpp"

namespace partimix::materials {
namespace {

constexpr double kR = 8.314462618;  // J/(mol K)

struct State {
  double density;      // [kg/m^3]
  double temperature;  // [K]
};

ThermalEosConfig tait(double rho0, double c0, double gamma) {
  ThermalEosConfig c;
  c.model = "tait";
  c.reference_density = rho0;
  c.sound_speed = c0;
  c.gamma = gamma;
  return c;
}

ThermalEosConfig ideal_gas(double molar_mass) {
  ThermalEosConfig c;
  c.model = "ideal_gas";
  c.molar_mass = molar_mass;
  return c;
}

ThermalEosConfig redlich_kwong(double molar_mass, double a, double b) {
  ThermalEosConfig c;
  c.model = "redlich_kwong";
  c.molar_mass = molar_mass;
  c.a = a;
  c.b = b;
  return c;
}

// Water: M = 18.015 g/mol, critical point Tc = 647.096 K, pc = 22.064 MPa (IAPWS-95), with the
// Redlich-Kwong constants from the critical point (Redlich & Kwong 1949).
constexpr double kWaterMolarMass = 0.018015;
constexpr double kWaterTc = 647.096;
constexpr double kWaterPc = 22.064e6;
const double kWaterA = 0.42748 * kR * kR * std::pow(kWaterTc, 2.5) / kWaterPc;
const double kWaterB = 0.08664 * kR * kWaterTc / kWaterPc;
constexpr double kAirMolarMass = 0.0289647;  // dry air [kg/mol]

std::unique_ptr<ThermalEquationOfState> build(const ThermalEosConfig& config) {
  auto eos = thermal_eos_registry().create(config.model, config);
  EXPECT_NE(eos, nullptr) << config.model;
  return eos;
}

// Checks the model's pressure against `formula(rho, T)` at `states`, to a relative 1e-12.
template <class Formula>
void expect_pressure(const ThermalEosConfig& config, const std::vector<State>& states,
                     Formula formula) {
  const auto eos = build(config);
  for (const State& s : states) {
    const double expected = formula(s.density, s.temperature);
    EXPECT_NEAR(eos->pressure(s.density, s.temperature), expected, 1.0e-12 * std::abs(expected))
        << config.model << " at rho = " << s.density << ", T = " << s.temperature;
  }
}

// Central difference of f at x with step h = 1e-5 x: truncation ~1e-10, round-off ~1e-11.
double central_difference(const std::function<double(double)>& f, double x) {
  const double h = 1.0e-5 * x;
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

// Checks both derivatives against central differences of the pressure, to a relative 1e-6.
void expect_derivatives(const ThermalEosConfig& config, const std::vector<State>& states) {
  const auto eos = build(config);
  for (const State& s : states) {
    const double rho = s.density;
    const double t = s.temperature;
    const double by_density =
        central_difference([&](double r) { return eos->pressure(r, t); }, rho);
    const double by_temperature =
        central_difference([&](double x) { return eos->pressure(rho, x); }, t);
    EXPECT_NEAR(eos->pressure_density_derivative(rho, t), by_density, 1.0e-6 * std::abs(by_density))
        << config.model << " at rho = " << rho << ", T = " << t;
    EXPECT_NEAR(eos->pressure_temperature_derivative(rho, t), by_temperature,
                1.0e-6 * std::abs(by_temperature))
        << config.model << " at rho = " << rho << ", T = " << t;
  }
}

const std::vector<State> kLiquidStates{
    {990.0, 300.0}, {1000.0, 300.0}, {1013.0, 350.0}, {1050.0, 500.0}};
const std::vector<State> kGasStates{{1.2, 293.15}, {0.1, 1500.0}, {50.0, 400.0}};
const std::vector<State> kSteamStates{{0.6, 373.15}, {10.0, 600.0}, {100.0, 900.0}, {300.0, 800.0}};

// (dp/dV)_T of the model at molar volume v, from its density derivative (dV/drho = -V^2/M).
double pressure_volume_derivative(const ThermalEquationOfState& eos, double molar_mass, double v,
                                  double t) {
  const double rho = molar_mass / v;
  return -eos.pressure_density_derivative(rho, t) * rho * rho / molar_mass;
}

TEST(ThermalEos, EveryModelIsRegistered) {
  for (const std::string name : {"tait", "ideal_gas", "redlich_kwong"})
    EXPECT_TRUE(thermal_eos_registry().contains(name)) << name;
}

TEST(ThermalEos, UnknownModelGivesNullptr) {
  ThermalEosConfig c;
  c.model = "peng_robinson";
  EXPECT_EQ(thermal_eos_registry().create(c.model, c), nullptr);
}

TEST(ThermalEos, TaitFollowsItsFormula) {
  // The seed's eq. 5 with p0 = rho0 c0^2 / gamma; temperature plays no part.
  expect_pressure(tait(1000.0, 20.0, 7.0), kLiquidStates, [](double rho, double) {
    return 1000.0 * 400.0 / 7.0 * (std::pow(rho / 1000.0, 7.0) - 1.0);
  });
  expect_pressure(tait(800.0, 35.0, 1.5), kLiquidStates, [](double rho, double) {
    return 800.0 * 35.0 * 35.0 / 1.5 * (std::pow(rho / 800.0, 1.5) - 1.0);
  });
}

TEST(ThermalEos, IdealGasFollowsItsFormula) {
  expect_pressure(ideal_gas(kAirMolarMass), kGasStates,
                  [](double rho, double t) { return rho * kR * t / kAirMolarMass; });
}

TEST(ThermalEos, RedlichKwongFollowsItsFormula) {
  // The seed's eq. 4 with V = M / rho.
  expect_pressure(redlich_kwong(kWaterMolarMass, kWaterA, kWaterB), kSteamStates,
                  [](double rho, double t) {
                    const double v = kWaterMolarMass / rho;
                    return kR * t / (v - kWaterB) - kWaterA / (std::sqrt(t) * v * (v + kWaterB));
                  });
}

TEST(ThermalEos, DerivativesMatchCentralDifferences) {
  expect_derivatives(ideal_gas(kAirMolarMass), kGasStates);
  expect_derivatives(redlich_kwong(kWaterMolarMass, kWaterA, kWaterB), kSteamStates);
  // Tait: the density derivative by differences; the temperature derivative is exactly 0.
  const auto liquid = build(tait(1000.0, 20.0, 7.0));
  for (const State& s : kLiquidStates) {
    const double by_density =
        central_difference([&](double r) { return liquid->pressure(r, s.temperature); }, s.density);
    EXPECT_NEAR(liquid->pressure_density_derivative(s.density, s.temperature), by_density,
                1.0e-6 * by_density);
    EXPECT_EQ(liquid->pressure_temperature_derivative(s.density, s.temperature), 0.0);
  }
}

TEST(ThermalEos, TaitDerivativeAtReferenceDensityIsSoundSpeedSquared) {
  const auto liquid = build(tait(1000.0, 20.0, 7.0));
  EXPECT_EQ(liquid->pressure(1000.0, 300.0), 0.0);
  EXPECT_DOUBLE_EQ(liquid->pressure_density_derivative(1000.0, 300.0), 400.0);
  EXPECT_DOUBLE_EQ(adiabatic_sound_speed(*liquid, 1000.0, 300.0, 4180.0), 20.0);
}

// rho(p) inverts p(rho) to 1e-12 over densities 0.95-1.05 rho0, and pressures below -p0 give 0.
TEST(ThermalEos, TaitDensityInvertsItsPressure) {
  const Tait liquid(1000.0, 20.0, 7.0);
  for (const double rho : {950.0, 990.0, 1000.0, 1010.0, 1050.0})
    EXPECT_NEAR(liquid.density(liquid.pressure(rho, 0.0)), rho, 1e-12 * rho);
  EXPECT_EQ(liquid.density(-1000.0 * 400.0 / 7.0 - 1.0), 0.0);
}

TEST(ThermalEos, IdealGasAdiabaticSoundSpeedIsSqrtGammaRTOverM) {
  // Air: c_v = 718 J/(kg K), c_p = c_v + R/M, gamma = c_p / c_v (about 1.4).
  const auto air = build(ideal_gas(kAirMolarMass));
  const double cv = 718.0;
  const double gamma = (cv + kR / kAirMolarMass) / cv;
  for (const State& s : kGasStates) {
    const double expected = std::sqrt(gamma * kR * s.temperature / kAirMolarMass);
    EXPECT_NEAR(adiabatic_sound_speed(*air, s.density, s.temperature, cv), expected,
                1.0e-12 * expected)
        << "T = " << s.temperature;
  }
}

// p_RK / p_ideal - 1 at molar volume V: to first order in 1/V, B / V with the second virial
// coefficient B = b - a / (R T^1.5).
TEST(ThermalEos, RedlichKwongTendsToTheIdealGasAtLowDensity) {
  const auto steam = build(redlich_kwong(kWaterMolarMass, kWaterA, kWaterB));
  const auto ideal = build(ideal_gas(kWaterMolarMass));
  const double v = 1.0e4 * kWaterB;
  const double rho = kWaterMolarMass / v;
  for (const double t : {288.0, 373.15, 1000.0, 1500.0, 3000.0}) {
    const double difference = steam->pressure(rho, t) / ideal->pressure(rho, t) - 1.0;
    const double virial = (kWaterB - kWaterA / (kR * std::pow(t, 1.5))) / v;
    EXPECT_NEAR(difference, virial, 1.0e-3 * std::abs(virial)) << "T = " << t;
    // Below 1e-4 wherever a / (b R T^1.5) < 2, i.e. above 1181 K for water.
    if (t > 1200.0) {
      EXPECT_LT(std::abs(difference), 1.0e-4) << "T = " << t;
    }
  }
}

// With a = 0.42748 R^2 Tc^2.5 / pc and b = 0.08664 R Tc / pc, the critical isotherm has an
// inflection with zero slope at V_c = 3.847 b, where Z_c = pc V_c / (R Tc) = 1/3. V_c is found
// as the root of (d2p/dV2)_Tc (a simple root, unlike the double root of (dp/dV)_Tc) by
// bisection on [2 b, 5 b], which holds no other inflection.
TEST(ThermalEos, RedlichKwongCriticalPoint) {
  const auto steam = build(redlich_kwong(kWaterMolarMass, kWaterA, kWaterB));
  const auto slope = [&](double v) {
    return pressure_volume_derivative(*steam, kWaterMolarMass, v, kWaterTc);
  };
  const auto curvature = [&](double v) { return central_difference(slope, v); };
  double low = 2.0 * kWaterB;
  double high = 5.0 * kWaterB;
  ASSERT_GT(curvature(low), 0.0);
  ASSERT_LT(curvature(high), 0.0);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (curvature(mid) > 0.0 ? low : high) = mid;
  }
  const double vc = 0.5 * (low + high);
  const double zc = kWaterPc * vc / (kR * kWaterTc);
  const double pc = steam->pressure(kWaterMolarMass / vc, kWaterTc);
  EXPECT_NEAR(zc, 1.0 / 3.0, 1.0e-3);
  EXPECT_NEAR(vc / kWaterB, 3.847, 1.0e-3 * 3.847);
  EXPECT_NEAR(pc, kWaterPc, 1.0e-3 * kWaterPc);
  // The slope at V_c is zero on the scale pc / V_c of the isotherm.
  EXPECT_LT(std::abs(slope(vc)) * vc / kWaterPc, 1.0e-3);
  RecordProperty("Zc", std::to_string(zc));
}

}  // namespace
}  // namespace partimix::materials
