// The CFD-DEM exchange (docs/cfd-dem.md): in a closed periodic box of water and moving glass
// grains without gravity, the momentum of fluid and grains together, less the momentum the
// coupling will take back from the fluid over the next step (D), stays what it was to round-off
// over many sub-cycled steps, the drag split and the pressure-gradient force included; the
// grains' volume is the void fraction's deficit; a coupled run resumes bit for bit from a
// checkpoint; the case errors name their key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "app/simulation.hpp"
#include "cfd/cfd_solver.hpp"
#include "core/error.hpp"
#include "coupling/cfd_dem_coupling.hpp"
#include "dem/dem_solver.hpp"
#include "support/case_run.hpp"

namespace partimix::coupling {
namespace {

using test_support::TempDir;

std::string periodic_box(const std::string& coupling) {
  return R"(solver: [cfd, dem]
dimensions: 3
domain: {min: [0, 0, 0], max: [0.04, 0.04, 0.04], periodic: [x, y, z]}
time: {end: 1, output_interval: 1, sub_steps: {dem: 4}}
fluid: {density: 1000, viscosity: 1.0e-3}
cfd: {cell_size: 0.005, momentum_tolerance: 1.0e-14, pressure_tolerance: 1.0e-12}
dem:
  species:
    - {name: glass, density: 2500, youngs_modulus: 1.0e7}
  fill:
    region: {shape: box, min: [0.005, 0.005, 0.005], max: [0.035, 0.035, 0.035]}
    count: 60
    radius: 0.0015
    settle_time: 0
couplings:
  - )" + coupling +
         "\n";
}

// Σ_f ρ ε_f u_f V over the open faces: the fluid's momentum in the predictor's own measure.
Vec3 fluid_momentum(const cfd::FluidSolver& fluid) {
  Vec3 sum = Vec3::Zero();
  const double mass = fluid.settings().density * fluid.grid().cell_volume();
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < fluid.velocity()[a].size(); ++f)
      if (fluid.mask().open_face[a][f])
        sum[a] += mass * fluid.face_void_fraction()[a][f] * fluid.velocity()[a][f];
  return sum;
}

Vec3 grain_momentum(const ParticleStore& grains) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < grains.size(); ++i)
    sum += grains.mass()[i] * grains.velocity()[i];
  return sum;
}

// The box's 60 steps with the coupling `item`: the largest drift of the momentum less D, and the
// grains' momentum at the end over the start's.
void momentum_is_kept(const std::string& item) {
  const TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, periodic_box(item));
  app::Simulation simulation = app::build_simulation(the_case);
  auto& fluid = dynamic_cast<cfd::CfdSolver&>(*simulation.methods[0].solver);
  auto& dem = dynamic_cast<dem::DemSolver&>(*simulation.methods[1].solver);
  auto& coupling = dynamic_cast<CfdDemCoupling&>(*simulation.couplings[0]);
  ParticleStore& grains = *simulation.methods[1].store;
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const double s = static_cast<double>(grains.id()[i]);
    grains.velocity()[i] = 0.2 * Vec3(std::sin(s), std::cos(1.7 * s), std::sin(2.3 * s + 1.0));
  }
  const Vec3 start = grain_momentum(grains);
  const double scale = 0.2 * grains.mass()[0] * static_cast<double>(grains.size());
  const int sub_steps = the_case.methods[1].sub_steps;
  const double dt = std::min(fluid.stable_dt(), sub_steps * dem.stable_dt());
  double t = 0.0;
  double largest = 0.0;
  double deferred = 0.0;
  for (int step = 0; step < 60; ++step) {
    // Measured with the void fraction the fluid's last step went to (the exchange maps anew).
    const Vec3 before = fluid_momentum(fluid.fluid()) + grain_momentum(grains);
    coupling.exchange_with_fluid(t, dt);
    const Vec3 total = before - coupling.deferred_momentum();
    largest = std::max(largest, (total - start).norm() / scale);
    deferred = std::max(deferred, coupling.deferred_momentum().norm() / scale);
    fluid.step(dt);
    coupling.exchange_with_grains(dt);
    for (int s = 0; s < sub_steps; ++s)
      dem.step(dt / sub_steps);
    t += dt;
  }
  std::printf(
      "%s: momentum drift %.2e, largest deferred %.2e, of the grains' initial 0.2 m/s "
      "momentum scale; grains to fluid %.3f\n",
      item.c_str(), largest, deferred, grain_momentum(grains).norm() / start.norm());
  EXPECT_LT(largest, 1e-12);
  // The grains gave much of their momentum to the fluid: the exchange is not idle.
  EXPECT_LT(grain_momentum(grains).norm(), 0.9 * start.norm());
}

TEST(CfdDemCoupling, MomentumOfFluidAndGrainsIsKeptToRoundOff) {
  momentum_is_kept("{type: cfd_dem}");
  // The virtual mass, which the fluid's step does not carry, comes back through D.
  momentum_is_kept("{type: cfd_dem, virtual_mass: true}");
  momentum_is_kept("{type: cfd_dem, void_fraction: divided}");
}

// The frames' `grain_source`, S_p at the cell centres, holds the total force the faces' S_e -
// K_f u give the fluid: Σ_c S_p,c V_c = Σ_f (S_e,f - K_f u_f) V over the open faces.
TEST(CfdDemCoupling, TheFramesGrainSourceHoldsTheGrainsForceOnTheFluid) {
  const TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, periodic_box("{type: cfd_dem}"));
  app::Simulation simulation = app::build_simulation(the_case);
  auto& solver = dynamic_cast<cfd::CfdSolver&>(*simulation.methods[0].solver);
  ParticleStore& grains = *simulation.methods[1].store;
  for (std::size_t i = 0; i < grains.size(); ++i)
    grains.velocity()[i] = Vec3(0.2, -0.1, 0.05);
  dynamic_cast<CfdDemCoupling&>(*simulation.couplings[0]).exchange_with_fluid(0.0, 1e-3);
  solver.step(1e-3);
  const cfd::FluidSolver& fluid = solver.fluid();
  const double volume = fluid.grid().cell_volume();
  Vec3 faces = Vec3::Zero();
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < fluid.velocity()[a].size(); ++f)
      if (fluid.mask().open_face[a][f])
        faces[a] += volume * (fluid.grain_source()[a][f] -
                              fluid.drag_coefficient()[a][f] * fluid.velocity()[a][f]);
  Vec3 cells = Vec3::Zero();
  bool found = false;
  for (const FrameArray& array : solver.grid_frame()->cell_arrays) {
    if (array.name != "grain_source")
      continue;
    found = true;
    for (std::size_t c = 0; c < fluid.grid().cell_count(); ++c)
      for (int a = 0; a < 3; ++a)
        cells[a] += volume * array.values[3 * c + static_cast<std::size_t>(a)];
  }
  ASSERT_TRUE(found);
  EXPECT_GT(faces.norm(), 0.0);
  EXPECT_LT((cells - faces).norm(), 1e-12 * faces.norm());
}

TEST(CfdDemCoupling, VoidFractionHoldsTheGrainsVolume) {
  const TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, periodic_box("{type: cfd_dem}"));
  app::Simulation simulation = app::build_simulation(the_case);
  dynamic_cast<CfdDemCoupling&>(*simulation.couplings[0]).exchange_with_fluid(0.0, 1e-4);
  const auto& fluid = dynamic_cast<cfd::CfdSolver&>(*simulation.methods[0].solver).fluid();
  double deficit = 0.0;
  for (const double eps : fluid.void_fraction())
    deficit += (1.0 - eps) * fluid.grid().cell_volume();
  const double volume = 60 * 4.0 / 3.0 * M_PI * std::pow(0.0015, 3);
  EXPECT_NEAR(deficit, volume, 1e-12 * volume);
}

// Grains falling through water in a closed tank onto its floor, checkpointed.
std::string tank(const std::string& end) {
  return R"(solver: [cfd, dem]
dimensions: 3
gravity: [0, 0, -9.81]
domain: {min: [0, 0, 0], max: [0.03, 0.03, 0.06]}
time: {end: )" +
         end + R"(, output_interval: 0.01, sample_interval: 0.002, checkpoint_interval: 0.01,
       dt: 1.0e-4, sub_steps: {dem: 5}}
walls:
  - {shape: box, min: [0, 0, 0], max: [0.03, 0.03, 0.06]}
fluid: {density: 1000, viscosity: 1.0e-3}
cfd: {cell_size: 0.005}
dem:
  species:
    - {name: glass, density: 2500, youngs_modulus: 1.0e7}
  fill:
    region: {shape: box, min: [0.003, 0.003, 0.03], max: [0.027, 0.027, 0.057]}
    count: 40
    radius: 0.0015
    settle_time: 0
couplings:
  - {type: cfd_dem}
)";
}

TEST(CfdDemCoupling, TheSecondHalfFromACheckpointIsTheRunThatWentThrough) {
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test_support::run_through_and_resumed(dir, tank("0.03"), tank("0.015")));
  EXPECT_EQ(test_support::read_file(dir / "whole" / "series.csv"),
            test_support::read_file(dir / "parts" / "series.csv"));
  for (const std::string frame : {"cfd_000003.vti", "dem_000003.vtp"})
    EXPECT_TRUE(test_support::read_file(dir / "whole" / "frames" / frame) ==
                test_support::read_file(dir / "parts" / "frames" / frame))
        << frame;
  // The kernel's support: 2 d_max = 6 mm raised to 1.5 h = 7.5 mm.
  const auto run = nlohmann::json::parse(test_support::read_file(dir / "whole" / "run.json"));
  EXPECT_DOUBLE_EQ(run.at("derived").at("couplings[0].kernel radius [m]").get<double>(), 0.0075);
}

std::string key_of_error(const std::string& text) {
  const TempDir dir;
  try {
    const io::Case the_case = test_support::load_case_text(dir, text);
    app::build_simulation(the_case);
  } catch (const InputError& error) {
    return error.location().key_path;
  }
  return "no error";
}

TEST(CfdDemCoupling, CaseErrorsNameTheirKey) {
  std::string no_dem = periodic_box("{type: cfd_dem}");
  no_dem.replace(no_dem.find("[cfd, dem]"), 10, "[cfd]");
  no_dem.replace(no_dem.find("dem: 4"), 6, "cfd: 1");
  no_dem = no_dem.substr(0, no_dem.find("dem:\n")) + no_dem.substr(no_dem.find("couplings:"));
  EXPECT_EQ(key_of_error(no_dem), "couplings[0].type");
  std::string fluid_sub_steps = periodic_box("{type: cfd_dem}");
  fluid_sub_steps.replace(fluid_sub_steps.find("dem: 4"), 6, "dem: 4, cfd: 2");
  EXPECT_EQ(key_of_error(fluid_sub_steps), "time.sub_steps.cfd");
  std::string fluid_first = periodic_box("{type: cfd_dem}");
  fluid_first.replace(fluid_first.find("[cfd, dem]"), 10, "[dem, cfd]");
  EXPECT_EQ(key_of_error(fluid_first), "solver");
  EXPECT_EQ(key_of_error(periodic_box("{type: cfd_dem, drag: stokes}")), "couplings[0].drag");
  EXPECT_EQ(key_of_error(periodic_box("{type: cfd_dem, min_void_fraction: 1.5}")),
            "couplings[0].min_void_fraction");
  EXPECT_EQ(key_of_error(periodic_box("{type: cfd_dem, virtual_mass_coefficient: -1}")),
            "couplings[0].virtual_mass_coefficient");
  // 8³ cells within reach of each of 60 grains, 30,720 weights, over a limit of 10,000.
  EXPECT_EQ(key_of_error(periodic_box("{type: cfd_dem, kernel_radius: 1.0e9}") +
                         "limits: {grid_nodes: 10000}\n"),
            "couplings[0].kernel_radius");
}

}  // namespace
}  // namespace partimix::coupling
