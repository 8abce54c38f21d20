// The methods of partimix by name (io/method_type.hpp): adding a method is its folder and one
// line here.
#include "cfd/cfd_method.hpp"
#include "dem/dem_method.hpp"
#include "io/method_type.hpp"
#include "mpm/mpm_method.hpp"
#include "sph/sph_method.hpp"

namespace partimix::io {

const Registry<MethodType>& method_registry() {
  static const Registry<MethodType> registry = [] {
    Registry<MethodType> r;
    r.add("sph", [] { return std::make_unique<sph::SphMethod>(); });
    r.add("dem", [] { return std::make_unique<dem::DemMethod>(); });
    r.add("mpm", [] { return std::make_unique<mpm::MpmMethod>(); });
    r.add("cfd", [] { return std::make_unique<cfd::CfdMethod>(); });
    return r;
  }();
  return registry;
}

InputError case_error(const Case& the_case, const std::string& key, const std::string& what) {
  return InputError(the_case.locate(key), what);
}

}  // namespace partimix::io
