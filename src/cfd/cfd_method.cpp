#include "cfd/cfd_method.hpp"

#include "cfd/cfd_solver.hpp"
#include "core/error.hpp"

namespace partimix::cfd {

std::shared_ptr<io::MethodSection> CfdMethod::read(io::Reader& root,
                                                   const io::Case& the_case) const {
  return read_cfd_section(root, the_case);
}

io::MethodInstance CfdMethod::build(const io::Case& the_case, const io::MethodSpec& spec,
                                    const io::BuildOptions& /*options*/) const {
  const CfdSection& section = dynamic_cast<const CfdSection&>(*spec.section);
  io::MethodInstance instance;
  instance.store = std::make_unique<ParticleStore>();
  try {
    instance.solver = std::make_unique<CfdSolver>(*instance.store, the_case.domain, section.config);
  } catch (const InputError& error) {
    throw io::case_error(the_case, error.location().key_path, error.message());
  }
  return instance;
}

}  // namespace partimix::cfd
