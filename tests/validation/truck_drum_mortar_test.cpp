// Mortar in a small truck drum (docs/truck-drum.md, "The mortar"): the grid fluid's two phases in
// the drum's rotating frame, its blades on the grid, with and without grains. The drum: 0.17 m
// long, head 0.05 m, cylinder 0.08 m in radius, opening 0.03 m, blades 20 mm high at seed 004's
// optimised 78 deg and 100/85/76 deg; its axis along x, the gravity tilted 15 deg; cells of
// 10 mm; a Bingham mortar of 2800 kg/m³ up to a level through the axis's middle, under air.
//
// - A whole cycle in a closed box (60 rpm, then -60 rpm from 0.6 s, to 1.2 s): the mortar's
//   volume Σ α ε V is kept to round-off (1e-10 of it; the transport is conservative by
//   construction, the box closed), and α stays within [0, 1] to the solves' residual (1e-6).
// - Discharge through the opening (an outlet at its plane) from the start of a reversed turn:
//   the volume discharged in 4 s at -60 rpm exceeds that at -30 rpm by at least a fifth (the
//   blades convey a fixed volume per turn while the drum runs full enough, so twice the speed
//   should give near twice the flow). Measured 3.4 mL against 1.5 mL since the outlet's
//   convection was mended (docs/cfd.md, "Convection: upwind or TVD"; 3.9 mL before), with the
//   interface compression (docs/cfd.md, "Interface compression"); 25.5 mL against 9.6 mL before it,
//   when the mortar spread into a foam of mortar and air that spilled over the lip, so that the
//   drum turned the other way, at +60 rpm, let 20.7 mL out too. What leaves is still mortar carried
//   up the wall and over the lip, which rises with the speed, not the blades' conveying, which
//   this test does not show (docs/truck-drum.md, "The mortar").
// - A uniform suspension at rest: 144 grains of 1 mm (2960 kg/m³, the seed's) in the mortar,
//   their species alternating, the drum still, 0.5 s: no grain moves more than 0.1 mm (Stokes
//   settling in η = 2 Pa s is 44 um/s; the start's pressure transient adds microns), and the
//   segregation degree does not change by more than 0.1 points. Here the gravity is along -z and
//   the mortar's level at a face of the cells: with the level tilted 15 deg to the grid, as in
//   the other tests, the staircase of α drives spurious currents (after 0.5 s at rest 1.4 cm/s
//   in the mortar and 0.2 m/s in the air at these cells, and grains moved up to 1.3 mm;
//   docs/cfd.md, "Two phases: volume of fluid", "What it is not").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/drum_segregation.hpp"
#include "app/run_clock.hpp"
#include "app/simulation.hpp"
#include "cfd/cfd_solver.hpp"
#include "geometry/truck_drum_shape.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

// The case's text: `solver`, the domain's x end, the rotation (a motion map, or none), the
// box's x+ side, and the rest (grains, couplings).
std::string drum_case(const std::string& solver, double x_end, const std::string& motion,
                      const std::string& sides, const std::string& rest) {
  return "solver: " + solver + R"(
dimensions: 3
gravity: [-2.5390, 0, -9.4757]
domain:
  min: [-0.01, -0.09, -0.09]
  max: [)" +
         std::to_string(x_end) +
         R"(, 0.09, 0.09]
time: {end: 1, output_interval: 1, sample_interval: 1}
fluid:
  density: 2800
  rheology: {model: bingham, yield_stress: 10, plastic_viscosity: 0.5, viscosity_max: 2}
  light_phase: {density: 1.2, viscosity: 1.8e-5}
  regions:
    - {shape: plane, point: [0.085, 0, 0], normal: [0.25882, 0, 0.96593]}
cfd:
  cell_size: 0.01
  rotating_frame: {wall: 0}
)" + sides +
         R"(walls:
  - shape: truck_drum
    axis_point: [0, 0, 0]
    axis: [1, 0, 0]
    head_radius: 0.05
    front_length: 0.05
    radius: 0.08
    cylinder_length: 0.06
    rear_length: 0.06
    opening_radius: 0.03
    blades: {height: 0.02, thickness: 0.004, helix_angle: 78, offset_angles: [100, 85, 76]}
    material: {youngs_modulus: 1.0e6, poisson_ratio: 0.3}
)" + motion +
         rest;
}

std::string rotation(double rpm, const std::string& schedule = "") {
  return "    motion: {type: rotation, axis_point: [0, 0, 0], axis: [1, 0, 0], rpm: " +
         std::to_string(rpm) + ", ramp_time: 0.2" + schedule + "}\n";
}

// Steps the simulation's clock from 0 to `end`.
void run_until(const io::Case& the_case, app::Simulation& simulation, double end) {
  app::RunClock clock(the_case, simulation);
  for (double t = 0.0; t < end - 1e-12;) {
    std::string why;
    const std::optional<double> dt = clock.next_step(end - t, why);
    ASSERT_TRUE(dt.has_value()) << why;
    clock.advance(t, *dt);
    t += *dt;
  }
}

// Σ of the cells' `volume` (α ε V, the mortar's), and α's range.
struct Mortar {
  double volume = 0.0;
  double lowest = 1.0;
  double highest = 0.0;
};

Mortar mortar(const app::Simulation& simulation) {
  Mortar m;
  for (const double v : simulation.methods[0].store->find_scalar("volume")->values)
    m.volume += v;
  const auto& solver = dynamic_cast<const cfd::CfdSolver&>(*simulation.methods[0].solver);
  for (const double a : solver.fluid().phase_fraction()) {
    m.lowest = std::min(m.lowest, a);
    m.highest = std::max(m.highest, a);
  }
  return m;
}

TEST(TruckDrumMortar, AWholeCycleKeepsTheMortarsVolume) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(
      dir, drum_case("cfd", 0.19, rotation(60.0, ", schedule: [{time: 0.6, rpm: -60}]"), "", ""));
  app::Simulation simulation = app::build_simulation(the_case);
  const double start = mortar(simulation).volume;
  ASSERT_NO_FATAL_FAILURE(run_until(the_case, simulation, 1.2));
  const Mortar end = mortar(simulation);
  std::printf("closed drum, a cycle: mortar %.9g -> %.9g m^3 (%.2e), alpha in [%.2e, 1 + %.2e]\n",
              start, end.volume, end.volume / start - 1.0, end.lowest, end.highest - 1.0);
  EXPECT_NEAR(end.volume, start, 1e-10 * start);
  EXPECT_GT(end.lowest, -1e-6);
  EXPECT_LT(end.highest, 1.0 + 1e-6);
}

double discharged_in(double rpm, double seconds) {
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(
      dir, drum_case("cfd", 0.17, rotation(rpm), "  sides: {x+: {wall: outlet}}\n", ""));
  app::Simulation simulation = app::build_simulation(the_case);
  const double start = mortar(simulation).volume;
  run_until(the_case, simulation, seconds);
  return start - mortar(simulation).volume;
}

TEST(TruckDrumMortar, DischargeRisesWithTheSpeed) {
  const double slow = discharged_in(-30.0, 4.0);
  const double fast = discharged_in(-60.0, 4.0);
  std::printf("discharged in 4 s: %.4g m^3 at -30 rpm, %.4g m^3 at -60 rpm\n", slow, fast);
  EXPECT_GT(slow, 0.0);
  EXPECT_GT(fast, 1.2 * slow);
}

// 144 grains on a 4 x 6 x 6 lattice in the mortar, clear of the blades, species alternating:
// along the axis at the middles of the segregation's slices 3 to 6 (of 10, 17 mm each), so that
// a drift of a fraction of a millimetre leaves each in its slice; 8 mm apart across.
std::string suspension() {
  std::string grains = R"(dem:
  species:
    - {name: a, density: 2960, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
    - {name: b, density: 2960, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
  grains:
)";
  const double slice = 0.17 / 10.0;
  int n = 0;
  for (int i = 3; i < 7; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k, ++n)
        grains += "    - {position: [" + std::to_string((i + 0.5) * slice) + ", " +
                  std::to_string(-0.02 + 0.008 * j) + ", " + std::to_string(-0.05 + 0.006 * k) +
                  "], radius: 0.0005, species: " + (n % 2 == 0 ? "a" : "b") + "}\n";
  return grains + "couplings:\n  - {type: cfd_dem, drag: gidaspow}\n";
}

double segregation(const io::Case& the_case, const ParticleStore& grains) {
  analysis::DrumMeasures options;
  options.drum = std::dynamic_pointer_cast<const geometry::TruckDrumShape>(the_case.walls[0].shape);
  options.coarse_species = 1;
  analysis::DrumSegregation measure(options);
  std::vector<double> values(measure.columns().size());
  measure.sample(grains, 0.0, values);
  return values[0];
}

TEST(TruckDrumMortar, AUniformSuspensionAtRestStaysPut) {
  const test_support::TempDir dir;
  std::string text = drum_case("[cfd, dem]", 0.19, "", "", suspension());
  const std::string frame = "  rotating_frame: {wall: 0}\n";
  text.erase(text.find(frame), frame.size());  // the drum is still: the lab's frame
  const std::string gravity = "[-2.5390, 0, -9.4757]";
  text.replace(text.find(gravity), gravity.size(), "[0, 0, -9.81]");
  const std::string level = "[0.25882, 0, 0.96593]";
  text.replace(text.find(level), level.size(), "[0, 0, 1]");  // at a face of the cells
  const std::string sampling = "sample_interval: 1}";
  text.replace(text.find(sampling), sampling.size(), "sample_interval: 1, sub_steps: {dem: 50}}");
  const io::Case the_case = test_support::load_case_text(dir, text);
  app::Simulation simulation = app::build_simulation(the_case);
  const ParticleStore& grains = *simulation.methods[1].store;
  std::vector<Vec3> start(grains.size());
  for (std::size_t i = 0; i < grains.size(); ++i)
    start[static_cast<std::size_t>(grains.id()[i])] = grains.position()[i];
  const double s0 = segregation(the_case, grains);
  ASSERT_NO_FATAL_FAILURE(run_until(the_case, simulation, 0.5));
  double moved = 0.0;
  for (std::size_t i = 0; i < grains.size(); ++i)
    moved = std::max(
        moved, (grains.position()[i] - start[static_cast<std::size_t>(grains.id()[i])]).norm());
  const double s1 = segregation(the_case, grains);
  std::printf("suspension at rest, 0.5 s: largest move %.3g m, segregation %.4f -> %.4f %%\n",
              moved, s0, s1);
  EXPECT_LT(moved, 1e-4);
  EXPECT_NEAR(s1, s0, 0.1);
}

}  // namespace
}  // namespace partimix
