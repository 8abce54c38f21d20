#include "app/simulation.hpp"

namespace partimix::app {

std::size_t Simulation::particle_count() const {
  std::size_t count = 0;
  for (const io::MethodInstance& method : methods)
    count += method.store->size();
  return count;
}

Simulation build_simulation(const io::Case& the_case, const io::BuildOptions& options) {
  Simulation simulation;
  for (const io::MethodSpec& spec : the_case.methods) {
    const auto type = io::method_registry().create(spec.name);
    simulation.methods.push_back(type->build(the_case, spec, options));
    auto& warnings = simulation.methods.back().warnings;
    simulation.warnings.insert(simulation.warnings.end(), warnings.begin(), warnings.end());
  }
  return simulation;
}

}  // namespace partimix::app
