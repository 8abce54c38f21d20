#pragma once
// The `mpm:` section of a case file (docs/case-reference.md, "mpm"): the grid, the shape
// function, the transfer and update, the granular materials and the regions filled with
// points. The walls come from the case's shared walls section with their `boundary`.
#include <memory>

#include "io/case.hpp"
#include "io/yaml_reader.hpp"
#include "mpm/config.hpp"

namespace partimix::mpm {

class MpmSection final : public io::MethodSection {
 public:
  MpmConfig config;
  // Points of tag 1 are a tracer for the mixing analyses.
  bool has_tracer() const override {
    for (const PointFill& fill : config.fills) {
      if (fill.tag == 1)
        return true;
    }
    return false;
  }
};

// Reads `mpm` from the root of a case file, with the walls and limits of `the_case`.
std::shared_ptr<MpmSection> read_mpm_section(io::Reader& root, const io::Case& the_case);

}  // namespace partimix::mpm
