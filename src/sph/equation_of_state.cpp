#include "sph/equation_of_state.hpp"

#include "sph/eos/linear_eos.hpp"
#include "sph/eos/tait_eos.hpp"

namespace partimix::sph {

const Registry<EquationOfState, const EosParameters&>& equation_of_state_registry() {
  static const Registry<EquationOfState, const EosParameters&> registry = [] {
    Registry<EquationOfState, const EosParameters&> r;
    r.add("linear", [](const EosParameters& p) {
      return std::make_unique<LinearEos>(p.reference_density, p.sound_speed);
    });
    r.add("tait", [](const EosParameters& p) {
      return std::make_unique<TaitEos>(p.reference_density, p.sound_speed, p.gamma);
    });
    return r;
  }();
  return registry;
}

}  // namespace partimix::sph
