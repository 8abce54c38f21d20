#pragma once
// The MPM method's entry in the method registry (io/method_type.hpp): it reads the `mpm`
// section and builds the material points and the grid (docs/mpm.md).
#include "io/method_type.hpp"
#include "mpm/mpm_section.hpp"

namespace partimix::mpm {

class MpmMethod final : public io::MethodType {
 public:
  std::vector<std::string> sections() const override { return {"mpm"}; }
  std::shared_ptr<io::MethodSection> read(io::Reader& root,
                                          const io::Case& the_case) const override;
  io::MethodInstance build(const io::Case& the_case, const io::MethodSpec& spec,
                           const io::BuildOptions& options) const override;
};

}  // namespace partimix::mpm
