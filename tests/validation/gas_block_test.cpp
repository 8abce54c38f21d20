// A uniform block of Redlich-Kwong gas on the multi-material scheme (docs/multi-material-sph.md,
// "Validation"; the seed's eq. 4 with its a and b as read there, M = 0.17 kg/mol, JP-8's vapour):
// the gas is given by its pressure, 10 MPa at 288 K, on a periodic 2D lattice. The scheme finds
// its density from eq. 4, and after 200 steps every particle's pressure is eq. 4 evaluated at
// its density and temperature to 1e-9, and 10 MPa to 1e-6 (the block is uniform, so it stays at
// rest: speeds below 1e-9 of the sound speed).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "particles/particle_store.hpp"
#include "sph/multi_material/multi_material_solver.hpp"

namespace partimix::sph {
namespace {

constexpr double kPressure = 10.0e6;    // [Pa]
constexpr double kTemperature = 288.0;  // [K]
constexpr double kMolarMass = 0.17;     // [kg/mol]
constexpr double kA = 1.295;            // [Pa m^6 K^0.5 mol^-2]
constexpr double kB = 4.9e-5;           // [m^3/mol]

// Eq. 4: p = R T / (V - b) - a / (T^(1/2) V (V + b)), V = M / rho.
double redlich_kwong(double density, double temperature) {
  const double v = kMolarMass / density;
  return materials::kMolarGasConstant * temperature / (v - kB) -
         kA / (std::sqrt(temperature) * v * (v + kB));
}

TEST(GasBlock, PressureFollowsTheRedlichKwongEquation) {
  MaterialSpec gas;
  gas.name = "vapour";
  gas.eos.model = "redlich_kwong";
  gas.eos.molar_mass = kMolarMass;
  gas.eos.a = kA;
  gas.eos.b = kB;
  gas.pressure = kPressure;
  gas.temperature = kTemperature;
  gas.specific_heat = 1500.0;
  Config config;
  config.scheme = "multi_material";
  config.spacing = 1e-5;
  config.multi_material.materials = {gas};
  Domain domain;
  domain.dimensions = 2;
  domain.lo = Vec3::Zero();
  domain.hi = Vec3(20 * config.spacing, 20 * config.spacing, 0.0);
  domain.periodic = {true, true, false};
  const Material material(gas, 0.0, 0);
  ParticleStore store;
  for (int iy = 0; iy < 20; ++iy)
    for (int ix = 0; ix < 20; ++ix) {
      const std::size_t i = store.size();
      store.resize(i + 1);
      store.position()[i] = Vec3((ix + 0.5) * config.spacing, (iy + 0.5) * config.spacing, 0.0);
      store.mass()[i] = material.initial_density() * config.spacing * config.spacing;
    }
  store.add_integer("material", "");
  MultiMaterialSolver solver(store, domain, config, Vec3::Zero());
  EXPECT_NEAR(redlich_kwong(material.initial_density(), kTemperature), kPressure, 1e-9 * kPressure);
  for (int step = 0; step < 200; ++step)
    solver.step(solver.stable_dt());
  const std::vector<double>& pressure = store.find_scalar("pressure")->values;
  const std::vector<double>& density = store.find_scalar("density")->values;
  const std::vector<double>& temperature = store.find_scalar("temperature")->values;
  const double sound = solver.derived_parameters().at("material vapour sound_speed [m/s]");
  for (std::size_t i = 0; i < store.size(); ++i) {
    ASSERT_NEAR(pressure[i], redlich_kwong(density[i], temperature[i]), 1e-9 * kPressure);
    ASSERT_NEAR(pressure[i], kPressure, 1e-6 * kPressure);
    ASSERT_LT(store.velocity()[i].norm(), 1e-9 * sound);
  }
}

}  // namespace
}  // namespace partimix::sph
