#pragma once
// A simulation built from a case (DESIGN.md, "One run"): one instance of each method the case
// runs (its particles, bodies and solver), in the order of `solver`, and the couplings between
// them. The app builds methods through the method registry only.
#include <memory>
#include <string>
#include <vector>

#include "coupling/coupling.hpp"
#include "io/case.hpp"
#include "io/method_type.hpp"

namespace partimix::app {

struct Simulation {
  std::vector<io::MethodInstance> methods;  // parallel to the case's methods
  std::vector<std::unique_ptr<coupling::Coupling>> couplings;
  std::vector<std::string> warnings;  // about the case as built, e.g. a see-through solid wall

  // All particles of all methods.
  std::size_t particle_count() const;
};

// Throws InputError (naming the case key) when the case cannot be built, e.g. particles that
// fall outside the domain or a periodic axis too short for the kernel.
Simulation build_simulation(const io::Case& the_case, const io::BuildOptions& options = {});

}  // namespace partimix::app
