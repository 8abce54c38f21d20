#pragma once
// A coupling as the case file and the run see it (DESIGN.md, "One run"; docs/architecture-notes.md,
// "Several methods in one run"): how it reads its item of `couplings` and how it joins the
// methods it couples, built before it. Each coupling defines one CouplingType;
// io/coupling_registry.cpp lists them by name, and neither the case loader nor the app names a
// concrete coupling.
#include <memory>
#include <span>

#include "core/registry.hpp"
#include "coupling/coupling.hpp"
#include "io/case.hpp"
#include "io/method_type.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

class CouplingType {
 public:
  virtual ~CouplingType() = default;
  // Reads the coupling's keys from its item; `the_case` holds the methods and their sections.
  // Throws InputError naming the key (e.g. when the case does not run the methods coupled).
  virtual std::shared_ptr<CouplingSection> read(Reader& item, const Case& the_case) const = 0;
  // Joins the methods of `methods` (parallel to the_case.methods).
  virtual std::unique_ptr<coupling::Coupling> build(const Case& the_case, const CouplingSpec& spec,
                                                    std::span<MethodInstance> methods) const = 0;
};

// The couplings by name (io/coupling_registry.cpp).
const Registry<CouplingType>& coupling_registry();

}  // namespace partimix::io
