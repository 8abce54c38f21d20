#include "core/derivative_free_search.hpp"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <stdexcept>

namespace partimix {
namespace {

struct Context {
  const SearchObjective* objective = nullptr;
  std::vector<double> lower;
  std::vector<double> width;
  std::vector<double> x;  // in the keys' units, reused
  std::exception_ptr failure;
  nlopt_opt opt = nullptr;
  int evaluations = 0;
  double best_value = std::numeric_limits<double>::infinity();
  std::vector<double> best;
};

double scaled_objective(unsigned n, const double* unit, double* /*gradient*/, void* data) {
  auto& context = *static_cast<Context*>(data);
  for (unsigned k = 0; k < n; ++k)
    context.x[k] = context.lower[k] + context.width[k] * unit[k];
  try {
    const double value = (*context.objective)(context.x);
    ++context.evaluations;
    if (value < context.best_value) {
      context.best_value = value;
      context.best = context.x;
    }
    return value;
  } catch (...) {
    context.failure = std::current_exception();
    nlopt_force_stop(context.opt);
    return std::numeric_limits<double>::infinity();
  }
}

nlopt_algorithm algorithm_of(const std::string& name) {
  if (name == "bobyqa")
    return NLOPT_LN_BOBYQA;
  if (name == "cobyla")
    return NLOPT_LN_COBYLA;
  if (name == "neldermead")
    return NLOPT_LN_NELDERMEAD;
  throw std::invalid_argument("unknown search algorithm '" + name + "'");
}

std::string reason_of(nlopt_result result) {
  switch (result) {
    case NLOPT_STOPVAL_REACHED:
      return "the target value was reached";
    case NLOPT_XTOL_REACHED:
      return "the steps became smaller than the tolerance";
    case NLOPT_FTOL_REACHED:
      return "the values stopped improving";
    case NLOPT_MAXEVAL_REACHED:
      return "the most evaluations were used";
    case NLOPT_FORCED_STOP:
      return "stopped";
    default:
      return result > 0 ? "converged" : "NLopt failed (code " + std::to_string(result) + ")";
  }
}

struct OptimiserDeleter {
  void operator()(nlopt_opt opt) const { nlopt_destroy(opt); }
};

}  // namespace

const std::vector<std::string>& search_algorithms() {
  static const std::vector<std::string> names{"bobyqa", "cobyla", "neldermead"};
  return names;
}

SearchResult minimise(const SearchObjective& objective, const std::vector<double>& lower,
                      const std::vector<double>& upper, const std::vector<double>& start,
                      const SearchSettings& settings) {
  const std::size_t n = lower.size();
  if (n == 0 || upper.size() != n || start.size() != n)
    throw std::invalid_argument("minimise: bounds and start need one value per variable");
  Context context;
  context.objective = &objective;
  context.lower = lower;
  context.width.resize(n);
  context.x.resize(n);
  std::vector<double> unit(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!(upper[k] > lower[k]))
      throw std::invalid_argument("minimise: each upper bound must exceed its lower bound");
    if (!(start[k] >= lower[k] && start[k] <= upper[k]))
      throw std::invalid_argument("minimise: the start must lie within the bounds");
    context.width[k] = upper[k] - lower[k];
    unit[k] = (start[k] - lower[k]) / context.width[k];
  }
  const std::unique_ptr<nlopt_opt_s, OptimiserDeleter> opt(
      nlopt_create(algorithm_of(settings.algorithm), static_cast<unsigned>(n)));
  context.opt = opt.get();
  const std::vector<double> zeros(n, 0.0);
  const std::vector<double> ones(n, 1.0);
  const std::vector<double> step(n, 0.25);
  nlopt_set_lower_bounds(opt.get(), zeros.data());
  nlopt_set_upper_bounds(opt.get(), ones.data());
  nlopt_set_initial_step(opt.get(), step.data());
  nlopt_set_min_objective(opt.get(), scaled_objective, &context);
  nlopt_set_maxeval(opt.get(), settings.max_evaluations);
  nlopt_set_xtol_abs1(opt.get(), settings.x_tolerance);
  if (settings.stop_value)
    nlopt_set_stopval(opt.get(), *settings.stop_value);
  double value = 0.0;
  const nlopt_result result = nlopt_optimize(opt.get(), unit.data(), &value);
  if (context.failure)
    std::rethrow_exception(context.failure);
  SearchResult out;
  out.best = context.best.empty() ? start : context.best;
  out.value = context.best_value;
  out.evaluations = context.evaluations;
  out.reason = reason_of(result);
  return out;
}

}  // namespace partimix
