// The couplings of partimix by name (io/coupling_type.hpp): adding a coupling is its files and
// one line here.
#include "coupling/cfd_dem_type.hpp"
#include "io/coupling_type.hpp"

namespace partimix::io {

const Registry<CouplingType>& coupling_registry() {
  static const Registry<CouplingType> registry = [] {
    Registry<CouplingType> r;
    r.add("cfd_dem", [] { return std::make_unique<coupling::CfdDemType>(); });
    return r;
  }();
  return registry;
}

}  // namespace partimix::io
