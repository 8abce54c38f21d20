#pragma once
// The evaluations of a design search (docs/design-loop.md, "Resuming"): each point the search
// asked for, its run folder and the figure it gave, kept in DIR/evaluations.json with what the
// search was (case, keys, figure, algorithm), so that a search run again in the same folder takes
// the points already evaluated from here: NLopt asks for the same points in the same order.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace partimix::app {

struct Evaluation {
  std::vector<double> x;
  std::string run;  // its folder in DIR
  double value = 0.0;
};

class EvaluationCache {
 public:
  // `search` describes the search; an existing file for another search is an InputError at
  // "--out", an unreadable one a RunError.
  EvaluationCache(std::filesystem::path file, nlohmann::json search);

  // The evaluation of exactly `x`, when made before.
  std::optional<Evaluation> find(const std::vector<double>& x) const;
  // Adds an evaluation and rewrites the file atomically.
  void add(const Evaluation& evaluation);
  const std::vector<Evaluation>& evaluations() const { return evaluations_; }

 private:
  void save() const;

  std::filesystem::path file_;
  nlohmann::json search_;
  std::vector<Evaluation> evaluations_;
};

}  // namespace partimix::app
