#include "app/simulation.hpp"

#include "io/coupling_type.hpp"

namespace partimix::app {

std::size_t Simulation::particle_count() const {
  std::size_t count = 0;
  for (const io::MethodInstance& method : methods)
    count += method.store->size();
  return count;
}

namespace {

// What `build` returns; an error that names a key but no file (from a layer below the case,
// e.g. the cell grid) is given the key's place in the case file.
template <class Build>
auto located(const io::Case& the_case, Build build) {
  try {
    return build();
  } catch (const InputError& error) {
    if (!error.location().file.empty())
      throw;
    throw InputError(the_case.locate(error.location().key_path), error.message());
  }
}

}  // namespace

Simulation build_simulation(const io::Case& the_case, const io::BuildOptions& options) {
  Simulation simulation;
  for (const io::MethodSpec& spec : the_case.methods) {
    simulation.methods.push_back(located(the_case, [&] {
      return io::method_registry().create(spec.name)->build(the_case, spec, options);
    }));
    auto& warnings = simulation.methods.back().warnings;
    simulation.warnings.insert(simulation.warnings.end(), warnings.begin(), warnings.end());
  }
  for (const io::CouplingSpec& spec : the_case.couplings)
    simulation.couplings.push_back(located(the_case, [&] {
      return io::coupling_registry().create(spec.type)->build(the_case, spec, simulation.methods);
    }));
  return simulation;
}

}  // namespace partimix::app
