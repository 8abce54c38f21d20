// Resuming in this process (docs/architecture-notes.md, "Checkpoints"), small enough for the
// sanitizers (tests/system has the kill-and-resume runs of the program): water and grains in one
// tank run past half time with checkpoints, then on to the end from the last checkpoint in a fresh
// simulation, and end bit for bit as the run that went through: series.csv, the series of an
// analysis on its own schedule, every frame of both methods, the collections and the figures;
// the same for superquadric grains, for a droplet with a total Lagrangian shell and for water
// with the variable smoothing length.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "io/case.hpp"
#include "io/checkpoint_folder.hpp"
#include "support/case_run.hpp"

namespace partimix::app {
namespace {

using test_support::read_file;
using test_support::TempDir;

std::string tank(const std::string& end) {
  return R"(solver: [sph, dem]
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.08, -0.08, -0.08]
  max: [0.18, 0.18, 0.2]
time:
  end: )" +
         end + R"(
  output_interval: 0.002
  sample_interval: 0.0005
  checkpoint_interval: 0.001
  dt: 2.0e-5
walls:
  - {shape: box, min: [0, 0, 0], max: [0.1, 0.1, 0.12], open: [z+]}
sph:
  spacing: 0.02
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: box, min: [0, 0, 0], max: [0.1, 0.1, 0.04]}
  tracer: {normal: [-1, 0, 0], point: [0.05, 0, 0]}
dem:
  species:
    - {name: a, density: 2500}
    - {name: b, density: 2500}
  fill:
    region: {shape: box, min: [0.01, 0.01, 0.05], max: [0.09, 0.09, 0.1]}
    count: 30
    radius: 0.004
    settle_time: 0
analyses:
  - {type: mixing, method: sph, region: box, min: [0, 0, 0], max: [0.1, 0.1, 0.05], cells: [2, 2, 1]}
  - {type: mixing, method: dem, region: box, min: [0, 0, 0], max: [0.1, 0.1, 0.12], cells: [2, 2, 1]}
  - {type: mixing, method: dem, name: fine, sample_interval: 0.0001, sample_from: 0.002,
     sample_until: 0.005, region: box, min: [0, 0, 0], max: [0.1, 0.1, 0.12], cells: [2, 2, 1]}
)";
}

TEST(ResumeInProcess, TheSecondHalfFromACheckpointIsTheRunThatWentThrough) {
  const TempDir dir;
  const io::Case whole = test_support::load_case_text(dir, tank("0.006"));
  const test_support::CaseRun through = test_support::run_case_into(whole, dir / "whole");
  ASSERT_EQ(through.summary.status, "completed");

  // Stopped at 0.0035 s: its newest checkpoint (0.003 s) lies before the step cut short to
  // end on time, so the run from it is the one that went through.
  const io::Case half = test_support::load_case_text(dir, tank("0.0035"));
  ASSERT_EQ(test_support::run_case_into(half, dir / "parts").summary.status, "completed");
  std::filesystem::path used;
  const StateArchive checkpoint =
      io::CheckpointFolder(dir / "parts" / "checkpoints").read_latest(&used);
  const test_support::CaseRun resumed =
      test_support::run_case_into(whole, dir / "parts", &checkpoint);
  ASSERT_EQ(resumed.summary.status, "completed");
  // This process's share: the steps after the checkpoint's, not the whole run's.
  EXPECT_EQ(resumed.summary.steps, through.summary.steps);
  EXPECT_EQ(through.summary.process_steps, through.summary.steps);
  EXPECT_EQ(resumed.summary.process_steps,
            resumed.summary.steps - static_cast<std::size_t>(checkpoint.integers("run/steps")[0]));
  EXPECT_LT(resumed.summary.process_wall_seconds, resumed.summary.wall_seconds);

  EXPECT_EQ(read_file(dir / "whole" / "series.csv"), read_file(dir / "parts" / "series.csv"));
  EXPECT_EQ(read_file(dir / "whole" / "series_fine.csv"),
            read_file(dir / "parts" / "series_fine.csv"));
  ASSERT_EQ(through.figures.size(), resumed.figures.size());
  for (const auto& [name, value] : through.figures) {
    const double again = resumed.figures.at(name);
    EXPECT_TRUE(value == again || (std::isnan(value) && std::isnan(again))) << name;
  }
  for (const std::string method : {"sph", "dem"}) {
    EXPECT_EQ(read_file(dir / "whole" / (method + ".pvd")),
              read_file(dir / "parts" / (method + ".pvd")));
    for (int k = 0; k <= 3; ++k) {
      const auto frame =
          std::filesystem::path("frames") / (method + "_00000" + std::to_string(k) + ".vtp");
      EXPECT_TRUE(read_file(dir / "whole" / frame) == read_file(dir / "parts" / frame)) << frame;
    }
  }
}

// Ellipsoids falling into a box and tumbling on its floor: the pairs' warm starts (the midway
// points) are part of the checkpoint, so the resumed run is the run that went through.
std::string ellipsoids(const std::string& end) {
  return R"(solver: dem
dimensions: 3
gravity: [0, 0, -9.81]
domain: {min: [-0.01, -0.01, -0.01], max: [0.06, 0.06, 0.06]}
time: {end: )" +
         end + R"(, output_interval: 0.02, sample_interval: 0.005, checkpoint_interval: 0.01}
walls:
  - {shape: plane, point: [0, 0, 0], normal: [0, 0, 1]}
  - {shape: plane, point: [0, 0, 0], normal: [1, 0, 0]}
  - {shape: plane, point: [0, 0, 0], normal: [0, 1, 0]}
  - {shape: plane, point: [0.05, 0.05, 0], normal: [-1, 0, 0]}
  - {shape: plane, point: [0.05, 0.05, 0], normal: [0, -1, 0]}
dem:
  species:
    - {name: a, density: 2500, shape: {half_axes: [0.002, 0.002, 0.004]}}
    - {name: b, density: 2500, shape: {half_axes: [0.002, 0.002, 0.004]}}
  fill:
    region: {shape: box, min: [0.0, 0.0, 0.0], max: [0.05, 0.05, 0.03]}
    count: 80
    settle_time: 0
analyses:
  - {type: mixing, region: box, min: [0, 0, 0], max: [0.05, 0.05, 0.05], cells: [2, 2, 1]}
)";
}

// The run that went through (dir/whole) and the resumed one (dir/parts) wrote the same series
// and the same frames 0 to `last` of `method`, none of them empty.
void expect_same_outputs(const TempDir& dir, const std::string& method, int last) {
  EXPECT_EQ(read_file(dir / "whole" / "series.csv"), read_file(dir / "parts" / "series.csv"));
  for (int k = 0; k <= last; ++k) {
    const auto frame =
        std::filesystem::path("frames") / (method + "_00000" + std::to_string(k) + ".vtp");
    ASSERT_FALSE(read_file(dir / "whole" / frame).empty()) << frame;
    EXPECT_TRUE(read_file(dir / "whole" / frame) == read_file(dir / "parts" / frame)) << frame;
  }
}

// A small gel droplet (cases/gel_droplet_2d.yaml shrunk to 14 spacings): a heated gas bubble,
// liquid and a total Lagrangian shell whose reference positions are part of the checkpoint, so
// the resumed run, its droplet series and its frames are the run that went through. `strength`:
// the shell's Johnson-Cook A, D1 and damage threshold.
std::string droplet(const std::string& end,
                    const std::string& strength = "A: 5.0e5, D1: 0.36, damage_threshold: 0.32") {
  return R"(solver: sph
dimensions: 2
domain: {min: [-3.0e-4, -3.0e-4], max: [3.0e-4, 3.0e-4]}
time: {end: )" +
         end + R"(, output_interval: 1.0e-6, sample_interval: 2.5e-7, checkpoint_interval: 1.0e-6}
sph:
  spacing: 1.0e-5
  lattice: {type: polar, centre: [0, 0], rings: golden}
  scheme: multi_material
  multi_material:
    ambient: {pressure: 1.0e7, temperature: 288}
  materials:
    - name: vapour
      eos: {model: redlich_kwong, molar_mass: 0.029, a: 1.295, b: 4.9e-5}
      pressure: 1.0e7
      temperature: 288
      specific_heat: 743
      conductivity: 0.026
      heat_source: 2.0e12
    - name: fuel
      eos: {model: tait, reference_density: 800, sound_speed: 50}
      temperature: 288
      specific_heat: 2000
      viscosity: 1.5e-3
      conductivity: 0.12
      surface_tension: 0.025
    - name: shell
      eos: {model: tait, reference_density: 1000, sound_speed: 300}
      temperature: 288
      specific_heat: 1500
      conductivity: 0.2
      solid:
        shear_modulus: 2.0e7
        formulation: total_lagrangian
        johnson_cook: {B: 8.0e6, n: 1, room_temperature: 288, melt_temperature: 600, )" +
         strength + R"(}
fluid:
  regions:
    - {shape: cylinder, center: [0, 0], radius: 5.0e-5, material: vapour}
    - {shape: cylinder, center: [0, 0], radius: 1.0e-4, material: fuel}
    - {shape: cylinder, center: [0, 0], radius: 1.4e-4, material: shell}
analyses:
  - {type: droplet, shell: shell, gas: vapour}
)";
}

TEST(ResumeInProcess, DropletWithATotalLagrangianShellResumesBitForBit) {
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(
      test_support::run_through_and_resumed(dir, droplet("3.0e-6"), droplet("2.5e-6")));
  expect_same_outputs(dir, "sph", 3);
}

// A weak shell starts to crack at about 1.7 us and has failed all round by the checkpoint the
// run resumes from (2 us; 66 of its 302 particles failed at 1.76 us, all at 2.01 us). The bonds
// the cracks cut are not in the checkpoint; they follow from the damage, so the resumed run cuts
// the same ones (restored without failing the damaged particles, it differs).
TEST(ResumeInProcess, DropletWhoseShellCracksResumesBitForBit) {
  const std::string weak = "A: 1.0e5, D1: 0.0045, damage_threshold: 0.0";
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(
      test_support::run_through_and_resumed(dir, droplet("3.0e-6", weak), droplet("2.5e-6", weak)));
  expect_same_outputs(dir, "sph", 3);
}

// A 2D water column collapsing with the variable smoothing length (docs/sph.md, "Variable
// smoothing length"): each h_i follows from the restored density, so the checkpoint needs none,
// and the time step, which the smallest h sets, is the same.
std::string variable_h_column(const std::string& end) {
  return R"(solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.05, -0.05]
  max: [0.25, 0.2]
time:
  end: )" +
         end + R"(
  output_interval: 0.02
  checkpoint_interval: 0.01
walls:
  - {shape: box, min: [0, 0], max: [0.2, 0.15], open: [y+]}
sph:
  spacing: 0.01
  smoothing_length: variable
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: box, min: [0, 0], max: [0.06, 0.1]}
)";
}

TEST(ResumeInProcess, VariableSmoothingLengthResumesBitForBit) {
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test_support::run_through_and_resumed(dir, variable_h_column("0.06"),
                                                                variable_h_column("0.035")));
  expect_same_outputs(dir, "sph", 3);
}

TEST(ResumeInProcess, EllipsoidsResumeBitForBit) {
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(
      test_support::run_through_and_resumed(dir, ellipsoids("0.1"), ellipsoids("0.065")));
  expect_same_outputs(dir, "dem", 5);
}

TEST(ResumeInProcess, ACheckpointOfOtherParticlesDoesNotFit) {
  const TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, tank("0.001"));
  ASSERT_EQ(test_support::run_case_into(the_case, dir / "out").summary.status, "completed");
  const StateArchive checkpoint = io::CheckpointFolder(dir / "out" / "checkpoints").read_latest();
  std::string text = tank("0.001");
  text.replace(text.find("count: 30"), 9, "count: 31");
  const io::Case other = test_support::load_case_text(dir, text);
  EXPECT_THROW(test_support::run_case_into(other, dir / "other", &checkpoint), StateError);
  EXPECT_FALSE(std::filesystem::exists(dir / "other" / "series.csv"))
      << "a checkpoint that does not fit must not write";
}

// A checkpoint made to look right (fuzz/README.md: the header repaired) with a grain of a
// species the case does not have, or a particle of another kind: refused, never stepped.
TEST(ResumeInProcess, ACheckpointWithIndicesTheCaseCannotHaveDoesNotFit) {
  const TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, tank("0.001"));
  ASSERT_EQ(test_support::run_case_into(the_case, dir / "out").summary.status, "completed");
  const StateArchive good = io::CheckpointFolder(dir / "out" / "checkpoints").read_latest();
  const auto damaged = [&good](const std::string& path, std::int64_t value) {
    StateArchive archive = good;
    const auto saved = good.integers(path);
    std::vector<std::int64_t> values(saved.begin(), saved.end());
    values.back() = value;
    archive.put_integers(path, values);
    return archive;
  };
  const StateArchive species = damaged("methods/dem/fields/species", 7);
  EXPECT_THROW(test_support::run_case_into(the_case, dir / "a", &species), StateError);
  const StateArchive kind = damaged("methods/sph/fields/kind", 5);
  EXPECT_THROW(test_support::run_case_into(the_case, dir / "b", &kind), StateError);
}

}  // namespace
}  // namespace partimix::app
