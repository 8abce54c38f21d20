#include "dem/normal_contact.hpp"

#include <memory>

#include "dem/hertz_contact.hpp"
#include "dem/linear_contact.hpp"

namespace partimix::dem {

const Registry<NormalContactLaw, const NormalLawParameters&>& normal_contact_registry() {
  static const Registry<NormalContactLaw, const NormalLawParameters&> registry = [] {
    Registry<NormalContactLaw, const NormalLawParameters&> r;
    r.add("hertz", [](const NormalLawParameters&) { return std::make_unique<HertzContact>(); });
    r.add("linear", [](const NormalLawParameters& p) {
      return std::make_unique<LinearContact>(p.stiffness);
    });
    return r;
  }();
  return registry;
}

}  // namespace partimix::dem
