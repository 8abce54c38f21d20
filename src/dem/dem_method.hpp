#pragma once
// The DEM method's entry in the method registry (io/method_type.hpp): it reads the `dem`
// section and builds the grains (docs/dem.md, "Filling"): inserted at random into the fill
// region, settled under gravity with the walls held still, split into two species by the fill's
// plane; then the walls' motions start at t = 0.
#include "dem/dem_section.hpp"
#include "io/method_type.hpp"

namespace partimix::dem {

class DemMethod final : public io::MethodType {
 public:
  std::vector<std::string> sections() const override { return {"dem"}; }
  std::shared_ptr<io::MethodSection> read(io::Reader& root,
                                          const io::Case& the_case) const override;
  io::MethodInstance build(const io::Case& the_case, const io::MethodSpec& spec,
                           const io::BuildOptions& options) const override;
};

}  // namespace partimix::dem
