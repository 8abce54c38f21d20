// Several methods in one run (docs/architecture-notes.md, "Several methods in one run"): water
// (SPH) and grains (DEM) in one tank, sharing its walls section, stepped on one clock with a
// coupling that only watches. Uncoupled, each method must come out bit for bit as it does
// alone: the same frames and the same series columns (named <method>.<column>), and with
// time.sub_steps the grains take k steps of dt / k per step of the clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "coupling/coupling.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix::app {
namespace {

using test_support::read_file;
using test_support::TempDir;

// A 0.1 m cubic tank open at the top; water 40 mm deep; 60 grains dropped into it from above.
std::string tank_case(const std::string& solver, const std::string& time_extra,
                      const std::string& end = "0.006") {
  return R"(name: tank
solver: )" +
         solver +
         R"(
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.04, -0.04, -0.04]
  max: [0.14, 0.14, 0.16]
time:
  end: )" +
         end + R"(
  output_interval: 0.003
  sample_interval: 0.001
)" + time_extra +
         R"(
walls:
  - shape: box
    min: [0, 0, 0]
    max: [0.1, 0.1, 0.12]
    open: [z+]
    material: {youngs_modulus: 1.0e7, poisson_ratio: 0.3}
)" +
         (solver.find("sph") != std::string::npos ? R"(sph:
  spacing: 0.01
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - {shape: box, min: [0, 0, 0], max: [0.1, 0.1, 0.04]}
)"
                                                  : "") +
         (solver.find("dem") != std::string::npos ? R"(dem:
  species:
    - {name: sand, density: 2500, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
  fill:
    region: {shape: box, min: [0.01, 0.01, 0.05], max: [0.09, 0.09, 0.1]}
    count: 60
    radius: 0.003
    settle_time: 0
)"
                                                  : "");
}

// Watches both methods at every step of the clock and writes nothing.
class WatchingCoupling final : public coupling::Coupling {
 public:
  explicit WatchingCoupling(const Simulation& simulation) : simulation_(simulation) {}
  void exchange(double time, double dt) override {
    times.push_back(time);
    steps.push_back(dt);
    particles = simulation_.particle_count();
  }
  std::vector<double> times;
  std::vector<double> steps;
  std::size_t particles = 0;

 private:
  const Simulation& simulation_;
};

struct Outputs {
  std::string series;
  std::vector<std::string> frames;  // the last frame of each method asked for
};

void run(const io::Case& the_case, const std::filesystem::path& out, Simulation& simulation) {
  ASSERT_EQ(test_support::run_simulation(the_case, simulation, out).summary.status, "completed");
}

// The column named `name` of a series.csv text, as text, one cell per row.
std::vector<std::string> column(const std::string& series, const std::string& name) {
  std::istringstream lines(series);
  std::string header;
  std::getline(lines, header);
  std::vector<std::string> names;
  std::istringstream cells(header);
  for (std::string cell; std::getline(cells, cell, ',');)
    names.push_back(cell.substr(0, cell.find(' ')));
  const auto index =
      static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  EXPECT_LT(index, names.size()) << name << " is not a column";
  std::vector<std::string> values;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream row(line);
    std::string cell;
    for (std::size_t k = 0; k <= index && std::getline(row, cell, ','); ++k) {
    }
    values.push_back(cell);
  }
  return values;
}

constexpr const char* kFixedStep = "  dt: 2.0e-5\n";

TEST(SeveralMethods, EachMethodIsBitwiseItsSingleRun) {
  const TempDir dir;
  Outputs alone;
  for (const std::string method : {"sph", "dem"}) {
    const io::Case the_case = test_support::load_case_text(dir, tank_case(method, kFixedStep));
    Simulation simulation = build_simulation(the_case);
    run(the_case, dir / method, simulation);
  }
  const io::Case both = test_support::load_case_text(dir, tank_case("[sph, dem]", kFixedStep));
  Simulation simulation = build_simulation(both);
  auto watching = std::make_unique<WatchingCoupling>(simulation);
  WatchingCoupling& watch = *watching;
  simulation.couplings.push_back(std::move(watching));
  run(both, dir / "both", simulation);

  const std::string series = read_file(dir / "both" / "series.csv");
  for (const std::string method : {"sph", "dem"}) {
    const std::string single = read_file(dir / method / "series.csv");
    EXPECT_EQ(column(series, "time"), column(single, "time"));
    for (const std::string name : {"kinetic_energy", "max_speed"})
      EXPECT_EQ(column(series, method + "." + name), column(single, name)) << method << name;
    for (const std::string frame : {"_000000.vtp", "_000001.vtp", "_000002.vtp"}) {
      const auto file = std::filesystem::path("frames") / (method + frame);
      EXPECT_TRUE(read_file(dir / "both" / file) == read_file(dir / method / file))
          << file << " differs from the single run's";
    }
    EXPECT_TRUE(std::filesystem::exists(dir / "both" / (method + ".pvd")));
  }
  ASSERT_EQ(watch.times.size(), 300u);  // 0.006 s in steps of 2e-5 s
  EXPECT_EQ(watch.times.front(), 0.0);
  EXPECT_EQ(watch.steps.front(), 2.0e-5);
  EXPECT_EQ(watch.particles, simulation.particle_count());
}

// Steps of 2^-14 s, four grain steps of 2^-16 s each, to 96 x 2^-14 s: all exact in binary,
// so dt / 4 is the grains' own step to the bit.
TEST(SeveralMethods, SubStepsGiveTheGrainsTheirOwnStep) {
  const TempDir dir;
  const std::string end = "0.005859375";
  const io::Case alone =
      test_support::load_case_text(dir, tank_case("dem", "  dt: 1.52587890625e-05\n", end));
  Simulation dem_alone = build_simulation(alone);
  run(alone, dir / "alone", dem_alone);
  const io::Case both = test_support::load_case_text(
      dir, tank_case("[sph, dem]", "  dt: 6.103515625e-05\n  sub_steps: {dem: 4}\n", end));
  Simulation simulation = build_simulation(both);
  run(both, dir / "both", simulation);
  const ParticleStore& a = *dem_alone.methods[0].store;
  const ParticleStore& b = *simulation.methods[1].store;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.position()[i], b.position()[i]) << "grain " << i;
    EXPECT_EQ(a.velocity()[i], b.velocity()[i]) << "grain " << i;
  }
}

TEST(SeveralMethods, AFixedStepAboveAMethodsStableStepFailsTheRun) {
  const TempDir dir;
  const io::Case the_case =
      test_support::load_case_text(dir, tank_case("[sph, dem]", "  dt: 1.0e-3\n"));
  Simulation simulation = build_simulation(the_case);
  const io::RunSummary summary =
      test_support::run_simulation(the_case, simulation, dir / "out").summary;
  EXPECT_EQ(summary.status, "failed");
  EXPECT_NE(summary.message.find("time.dt = 0.001 s exceeds the stable step of method sph"),
            std::string::npos)
      << summary.message;
}

}  // namespace
}  // namespace partimix::app
