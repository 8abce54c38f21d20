#include "mpm/mpm_method.hpp"

#include "core/error.hpp"
#include "mpm/mpm_solver.hpp"

namespace partimix::mpm {

std::shared_ptr<io::MethodSection> MpmMethod::read(io::Reader& root,
                                                   const io::Case& the_case) const {
  return read_mpm_section(root, the_case);
}

// The points are laid the same way for a restore (their number defines the fields); the
// checkpoint then replaces their state.
io::MethodInstance MpmMethod::build(const io::Case& the_case, const io::MethodSpec& spec,
                                    const io::BuildOptions& /*options*/) const {
  const MpmSection& section = dynamic_cast<const MpmSection&>(*spec.section);
  io::MethodInstance instance;
  instance.store = std::make_unique<ParticleStore>();
  try {
    instance.solver = std::make_unique<MpmSolver>(*instance.store, the_case.domain, section.config,
                                                  the_case.gravity, the_case.limits);
  } catch (const InputError& error) {
    throw io::case_error(the_case, error.location().key_path, error.message());
  }
  return instance;
}

}  // namespace partimix::mpm
