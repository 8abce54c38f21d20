#pragma once
// The grid fluid's entry in the method registry (io/method_type.hpp): it reads the `fluid` and
// `cfd` sections and builds the grid and its fluid (docs/cfd.md).
#include "cfd/cfd_section.hpp"
#include "io/method_type.hpp"

namespace partimix::cfd {

class CfdMethod final : public io::MethodType {
 public:
  std::vector<std::string> sections() const override { return {"cfd", "fluid"}; }
  std::shared_ptr<io::MethodSection> read(io::Reader& root,
                                          const io::Case& the_case) const override;
  io::MethodInstance build(const io::Case& the_case, const io::MethodSpec& spec,
                           const io::BuildOptions& options) const override;
};

}  // namespace partimix::cfd
