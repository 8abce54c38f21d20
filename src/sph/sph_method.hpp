#pragma once
// The SPH method's entry in the method registry (io/method_type.hpp): it reads the `sph` and
// `fluid` sections and builds the weakly-compressible solver over the fluid and wall particles.
#include "io/method_type.hpp"

namespace partimix::sph {

class SphMethod final : public io::MethodType {
 public:
  std::vector<std::string> sections() const override { return {"sph", "fluid"}; }
  std::shared_ptr<io::MethodSection> read(io::Reader& root,
                                          const io::Case& the_case) const override;
  io::MethodInstance build(const io::Case& the_case, const io::MethodSpec& spec,
                           const io::BuildOptions& options) const override;
};

}  // namespace partimix::sph
