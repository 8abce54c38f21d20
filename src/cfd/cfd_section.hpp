#pragma once
// The `fluid:` and `cfd:` sections of a case file for the grid fluid (docs/case-reference.md,
// "cfd"): the fluid's density and rheology, the grid, the numerics and the box's sides. The
// walls come from the case's shared walls section, as blocked cells.
#include <memory>

#include "cfd/config.hpp"
#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::cfd {

class CfdSection final : public io::MethodSection {
 public:
  CfdConfig config;
  bool has_tracer() const override { return false; }
};

// Reads `fluid` and `cfd` from the root of a case file, with the walls and limits of `the_case`.
std::shared_ptr<CfdSection> read_cfd_section(io::Reader& root, const io::Case& the_case);

}  // namespace partimix::cfd
