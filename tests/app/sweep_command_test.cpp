// `partimix sweep` end to end on the Poiseuille case cut to a few steps: one run per
// combination, each in its own folder, gathered in sweep.csv; bad --vary writes nothing; a
// failed run or Ctrl-C still leaves the table. And on the seed's vessel, coarse and short: the
// Np-Re plot with its fitted slope.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstddef>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::vector<std::vector<std::string>> read_csv_cells(const fs::path& file) {
  std::vector<std::vector<std::string>> cells;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    cells.emplace_back();
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.back().push_back(cell);
  }
  return cells;
}

// The first `count` cells of a row (fewer if it is shorter).
std::vector<std::string> first(const std::vector<std::string>& row, std::size_t count) {
  return {row.begin(), row.begin() + static_cast<std::ptrdiff_t>(std::min(count, row.size()))};
}

class SweepCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.write("case.yaml",
                   read_file(fs::path(PARTIMIX_SOURCE_DIR) / "cases/poiseuille_2d.yaml"));
  }

  Outcome sweep(const std::vector<std::string>& options) const {
    std::vector<std::string> arguments{"sweep", "case.yaml"};
    arguments.insert(arguments.end(), options.begin(), options.end());
    return run_partimix(scratch_, arguments);
  }

  Scratch scratch_;
};

TEST_F(SweepCommand, RunsEveryCombinationIntoOneTable) {
  const Outcome outcome = sweep({"--vary", "fluid.viscosity=1e-3,2e-3", "--vary",
                                 "time.end=0.002,0.004", "--jobs", "2", "--threads", "1"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const fs::path dir = scratch_.work() / "out" / "poiseuille_2d_sweep";
  const auto cells = read_csv_cells(dir / "sweep.csv");
  ASSERT_EQ(cells.size(), 5u);
  EXPECT_THAT(first(cells[0], 4), ElementsAre("run", "fluid.viscosity", "time.end", "status"));
  const std::vector<std::vector<std::string>> expected{{"run_000", "1e-3", "0.002", "completed"},
                                                       {"run_001", "1e-3", "0.004", "completed"},
                                                       {"run_002", "2e-3", "0.002", "completed"},
                                                       {"run_003", "2e-3", "0.004", "completed"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(first(cells[i + 1], 4), expected[i]) << "row " << i;
    const nlohmann::json run = read_json(dir / expected[i][0] / "run.json");
    EXPECT_EQ(run.at("case").at("fluid").at("viscosity"), std::stod(expected[i][1]));
    EXPECT_EQ(run.at("case").at("time").at("end"), std::stod(expected[i][2]));
    EXPECT_EQ(run.at("run").at("threads"), 1);
  }
  EXPECT_THAT(outcome.err, HasSubstr("run_003  2e-3"));
}

struct BadVaryCase {
  const char* name;
  std::string vary;
  std::string message;  // what follows "error: --vary: "
};

const BadVaryCase kBadVaries[] = {
    {"NoEquals", "fluid.viscosity", "fluid.viscosity: expected KEY=v1,v2"},
    {"NoValues", "fluid.viscosity=", "fluid.viscosity: no values"},
    {"UnknownKey", "fluid.viscosty=1,2", "fluid.viscosty: unknown key 'viscosty'"},
    {"WrongType", "fluid.viscosity=1e-3,abc", "fluid.viscosity: expected a number, got 'abc'"},
};

class BadVary : public SweepCommand, public ::testing::WithParamInterface<BadVaryCase> {};

TEST_P(BadVary, ExitsWithCode2AndWritesNothing) {
  const Outcome outcome = sweep({"--vary", "time.end=0.002,0.004", "--vary", GetParam().vary});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("error: --vary: " + GetParam().message));
  EXPECT_THAT(scratch_.work_entries(), ElementsAre("case.yaml"));
}

INSTANTIATE_TEST_SUITE_P(Texts, BadVary, ::testing::ValuesIn(kBadVaries),
                         [](const auto& variant) { return std::string(variant.param.name); });

TEST_F(SweepCommand, AFailedRunLeavesTheOthersAndTheTable) {
  // A spacing wider than the channel passes validation but generates no particles.
  const Outcome outcome = sweep(
      {"--vary", "sph.spacing=5e-5,0.01", "--set", "time.end=0.002", "--out", "s", "-t", "1"});
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
  const auto cells = read_csv_cells(scratch_.work() / "s" / "sweep.csv");
  ASSERT_EQ(cells.size(), 3u);
  EXPECT_THAT(first(cells[1], 3), ElementsAre("run_000", "5e-5", "completed"));
  EXPECT_THAT(first(cells[2], 3), ElementsAre("run_001", "0.01", "failed"));
  EXPECT_THAT(outcome.err, HasSubstr("see s/run_001/log.txt"));
  EXPECT_THAT(read_file(scratch_.work() / "s" / "run_001" / "log.txt"),
              HasSubstr("no lattice point at spacing 0.01 m lies inside this region"));
}

TEST_F(SweepCommand, SigintEndsTheRunningRunAndSkipsTheRest) {
  Child child(scratch_,
              {"sweep", "case.yaml", "--vary", "time.end=1000,2000", "--out", "s", "-t", "1"});
  ASSERT_TRUE(wait_for_file(scratch_.work() / "s" / "run_000" / "run.json"));
  child.signal(SIGINT);
  const Outcome outcome = child.wait();
  EXPECT_EQ(outcome.exit_code, 130) << outcome.err;
  const auto cells = read_csv_cells(scratch_.work() / "s" / "sweep.csv");
  ASSERT_EQ(cells.size(), 3u);
  EXPECT_THAT(first(cells[1], 3), ElementsAre("run_000", "1000", "interrupted"));
  EXPECT_THAT(first(cells[2], 3), ElementsAre("run_001", "2000", "skipped"));
}

TEST(SweepOfAVessel, WritesTheNpRePlotWithItsFittedSlope) {
  // The seed's vessel, very coarse (dp = 40 mm, plate 120 mm = 2h) and 0.1 s long, at Re = 10
  // and 1: the sweep gathers Re and Np, fits the power law and draws np_re.png. Even in the
  // start-up the torque grows with the viscosity, so Np falls with Re.
  const Scratch scratch;
  const std::string vessel = std::string(PARTIMIX_SOURCE_DIR) + "/cases/youcefi_vessel.yaml";
  const Outcome outcome = run_partimix(scratch, {"sweep",  vessel,
                                                 "--vary", "fluid.viscosity=2.835,28.35",
                                                 "--out",  "s",
                                                 "-t",     "1",
                                                 "--set",  "sph.spacing=0.04",
                                                 "--set",  "walls[1].width=0.12",
                                                 "--set",  "domain.min=[-0.3,-0.3,-0.2]",
                                                 "--set",  "domain.max=[0.3,0.3,0.5]",
                                                 "--set",  "walls[1].motion.rpm=60",
                                                 "--set",  "walls[1].motion.ramp_time=0.01",
                                                 "--set",  "sph.max_velocity=0.5",
                                                 "--set",  "time.end=0.1",
                                                 "--set",  "output.frames=false"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto cells = read_csv_cells(scratch.work() / "s" / "sweep.csv");
  ASSERT_EQ(cells.size(), 3u);
  EXPECT_THAT(first(cells[0], 6),
              ElementsAre("run", "fluid.viscosity", "status", "Np [-]", "Np_total [-]", "Re [-]"));
  std::smatch slope;
  ASSERT_TRUE(std::regex_search(outcome.out, slope, std::regex("slope = (\\S+)"))) << outcome.out;
  EXPECT_LT(std::stod(slope[1].str()), 0.0);
  EXPECT_EQ(read_file(scratch.work() / "s" / "np_re.png").substr(0, 4), "\x89PNG");
}

}  // namespace
}  // namespace partimix::cli_test
