#include "analysis/analysis.hpp"
#include "analysis/front_position.hpp"

namespace partimix::analysis {

const Registry<Analysis, const AnalysisOptions&>& analysis_registry() {
  static const Registry<Analysis, const AnalysisOptions&> registry = [] {
    Registry<Analysis, const AnalysisOptions&> r;
    r.add("front_position",
          [](const AnalysisOptions& o) { return std::make_unique<FrontPosition>(o.axis); });
    return r;
  }();
  return registry;
}

}  // namespace partimix::analysis
