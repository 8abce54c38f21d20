// The design loop's search (core/derivative_free_search, docs/design-loop.md) on analytical
// stand-ins for a simulation: each NLopt method finds the minimum of a quadratic bowl whose
// optimum lies off-centre in a box of keys of different scales within 1e-3 of each range; a
// target value stops the search at the first point that reaches it; the same objective gives the
// same points in the same order (what resuming relies on); one key works; an objective's
// exception stops the search and comes out; bad bounds are refused.
#include "core/derivative_free_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace partimix {
namespace {

// A bowl with its minimum 0 at (78, 85): a helix angle in [65, 85] and an offset in [0, 180].
double bowl(const std::vector<double>& x) {
  return std::pow((x[0] - 78.0) / 20.0, 2) + 3.0 * std::pow((x[1] - 85.0) / 180.0, 2);
}

const std::vector<double> kLower{65.0, 0.0};
const std::vector<double> kUpper{85.0, 180.0};
const std::vector<double> kStart{70.0, 90.0};

TEST(DerivativeFreeSearch, EachMethodFindsTheBowlsMinimum) {
  for (const std::string& algorithm : search_algorithms()) {
    SearchSettings settings;
    settings.algorithm = algorithm;
    settings.max_evaluations = 400;
    settings.x_tolerance = 1e-6;
    const SearchResult result = minimise(bowl, kLower, kUpper, kStart, settings);
    EXPECT_NEAR(result.best[0], 78.0, 1e-3 * 20.0) << algorithm;
    EXPECT_NEAR(result.best[1], 85.0, 1e-3 * 180.0) << algorithm;
    EXPECT_LT(result.value, 1e-5) << algorithm;
    EXPECT_LE(result.evaluations, 400) << algorithm;
  }
}

TEST(DerivativeFreeSearch, ATargetStopsAtTheFirstPointThatReachesIt) {
  SearchSettings settings;
  settings.max_evaluations = 400;
  settings.stop_value = 0.01;
  int calls = 0;
  double last = 0.0;
  const SearchResult result = minimise(
      [&](const std::vector<double>& x) {
        ++calls;
        last = bowl(x);
        return last;
      },
      kLower, kUpper, kStart, settings);
  EXPECT_LE(result.value, 0.01);
  EXPECT_EQ(last, result.value);
  EXPECT_EQ(result.evaluations, calls);
  EXPECT_LT(calls, 40);
}

TEST(DerivativeFreeSearch, TheSameObjectiveGivesTheSamePoints) {
  std::vector<std::vector<double>> first;
  std::vector<std::vector<double>> second;
  SearchSettings settings;
  settings.max_evaluations = 15;
  minimise(
      [&](const std::vector<double>& x) {
        first.push_back(x);
        return bowl(x);
      },
      kLower, kUpper, kStart, settings);
  minimise(
      [&](const std::vector<double>& x) {
        second.push_back(x);
        return bowl(x);
      },
      kLower, kUpper, kStart, settings);
  EXPECT_GE(first.size(), 5u);
  EXPECT_EQ(first, second);
}

TEST(DerivativeFreeSearch, OneKeyIsSearchedToo) {
  for (const std::string& algorithm : search_algorithms()) {
    SearchSettings settings;
    settings.algorithm = algorithm;
    settings.max_evaluations = 200;
    settings.x_tolerance = 1e-6;
    const SearchResult result =
        minimise([](const std::vector<double>& x) { return std::pow(x[0] - 0.3, 2); }, {-1.0},
                 {2.0}, {1.5}, settings);
    EXPECT_NEAR(result.best[0], 0.3, 3e-3) << algorithm << ": " << result.reason;
  }
}

TEST(DerivativeFreeSearch, AnObjectivesExceptionStopsTheSearch) {
  int calls = 0;
  EXPECT_THROW(minimise(
                   [&](const std::vector<double>& x) {
                     if (++calls == 3)
                       throw std::runtime_error("a run failed");
                     return bowl(x);
                   },
                   kLower, kUpper, kStart, SearchSettings{}),
               std::runtime_error);
  EXPECT_EQ(calls, 3);
}

TEST(DerivativeFreeSearch, BadBoundsAndAlgorithmsAreRefused) {
  const auto search = [](std::vector<double> lower, std::vector<double> upper,
                         std::vector<double> start, std::string algorithm = "bobyqa") {
    SearchSettings settings;
    settings.algorithm = std::move(algorithm);
    return minimise(bowl, lower, upper, start, settings);
  };
  EXPECT_THROW(search({65.0, 0.0}, {65.0, 180.0}, {65.0, 90.0}), std::invalid_argument);
  EXPECT_THROW(search(kLower, kUpper, {90.0, 90.0}), std::invalid_argument);
  EXPECT_THROW(search(kLower, kUpper, {70.0}), std::invalid_argument);
  EXPECT_THROW(search(kLower, kUpper, kStart, "newton"), std::invalid_argument);
}

}  // namespace
}  // namespace partimix
