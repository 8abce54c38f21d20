#include "coupling/drag_law.hpp"

#include <cmath>

#include "coupling/drag_laws/di_felice.hpp"
#include "coupling/drag_laws/gidaspow.hpp"

namespace partimix::coupling {

double schiller_naumann_cd_re(double re) {
  return re < 1000.0 ? 24.0 * (1.0 + 0.15 * std::pow(re, 0.687)) : 0.44 * re;
}

const Registry<DragLaw>& drag_law_registry() {
  static const Registry<DragLaw> registry = [] {
    Registry<DragLaw> r;
    r.add("gidaspow", [] { return std::make_unique<Gidaspow>(); });
    r.add("gidaspow_blended", [] { return std::make_unique<GidaspowBlended>(); });
    r.add("di_felice", [] { return std::make_unique<DiFelice>(); });
    return r;
  }();
  return registry;
}

}  // namespace partimix::coupling
