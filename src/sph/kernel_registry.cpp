#include <memory>

#include "sph/kernel.hpp"
#include "sph/kernels/cubic_spline.hpp"
#include "sph/kernels/hyperbolic.hpp"
#include "sph/kernels/wendland_c2.hpp"

namespace partimix::sph {

const Registry<Kernel>& kernel_registry() {
  static const Registry<Kernel> registry = [] {
    Registry<Kernel> r;
    r.add("cubic_spline", [] { return std::make_unique<CubicSpline>(); });
    r.add("wendland_c2", [] { return std::make_unique<WendlandC2>(); });
    r.add("hyperbolic", [] { return std::make_unique<Hyperbolic>(); });
    return r;
  }();
  return registry;
}

}  // namespace partimix::sph
