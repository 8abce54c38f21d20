#pragma once
// The CFD-DEM coupling's entry in the coupling registry (io/coupling_type.hpp): it reads its item
// of `couplings` (docs/case-reference.md, "couplings") and joins the case's `cfd` and `dem`
// methods (coupling/cfd_dem_coupling.hpp).
#include "coupling/cfd_dem_settings.hpp"
#include "io/coupling_type.hpp"

namespace partimix::coupling {

class CfdDemSection final : public io::CouplingSection {
 public:
  CfdDemSettings settings;
};

class CfdDemType final : public io::CouplingType {
 public:
  std::shared_ptr<io::CouplingSection> read(io::Reader& item,
                                            const io::Case& the_case) const override;
  std::unique_ptr<Coupling> build(const io::Case& the_case, const io::CouplingSpec& spec,
                                  std::span<io::MethodInstance> methods) const override;
};

}  // namespace partimix::coupling
