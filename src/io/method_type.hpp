#pragma once
// A method as the case file and the run see it (DESIGN.md, "One run"; docs/architecture-notes.md,
// "Methods"): the sections of the case it reads, how it reads them, and how it builds its solver
// from a case. Each method folder defines one MethodType; io/method_registry.cpp lists them by
// name, and neither the case loader nor the app names a concrete method.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/phase_monitor.hpp"
#include "core/registry.hpp"
#include "geometry/moving_bodies.hpp"
#include "io/case.hpp"
#include "io/yaml_reader.hpp"
#include "particles/particle_store.hpp"
#include "particles/solver.hpp"

namespace partimix::io {

// A method built from a case: its particles, the bodies that move its walls (null when it moves
// them itself or has none) and its solver, which refers to both.
struct MethodInstance {
  std::unique_ptr<ParticleStore> store;
  std::unique_ptr<geometry::MovingBodies> bodies;
  std::unique_ptr<Solver> solver;
  std::vector<std::string> warnings;  // about the case as built, e.g. a see-through solid wall
  // Bodies (wall indices) whose loads are unreliable, and why: the figures of the analyses of
  // their loads carry it as a caveat.
  std::map<int, std::string> load_caveats;
};

struct BuildOptions {
  // The state will be restored from a checkpoint: skip the set-up whose result the checkpoint
  // replaces (e.g. settling grains), keep what defines the fields and their sizes.
  bool for_restore = false;
  // Told how long set-up phases progress, and asked whether to stop; none: silent, unstoppable.
  PhaseMonitor* monitor = nullptr;
};

class MethodType {
 public:
  virtual ~MethodType() = default;
  // The top-level keys of the case file this method reads (e.g. "sph", "fluid").
  virtual std::vector<std::string> sections() const = 0;
  // Reads the method's sections from `root`; `the_case` holds what was read before (domain,
  // gravity, time, walls). Throws InputError naming the key.
  virtual std::shared_ptr<MethodSection> read(Reader& root, const Case& the_case) const = 0;
  // Builds the method of `spec` (one of the_case.methods). Throws InputError naming the case key
  // when the case cannot be built.
  virtual MethodInstance build(const Case& the_case, const MethodSpec& spec,
                               const BuildOptions& options) const = 0;
};

// The methods by name (io/method_registry.cpp).
const Registry<MethodType>& method_registry();

// An InputError at `key` of the case, found when the case is built: it points at the line and
// column where the key (or the nearest enclosing one) was written (Case::locate).
InputError case_error(const Case& the_case, const std::string& key, const std::string& what);

}  // namespace partimix::io
