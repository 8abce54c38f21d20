#pragma once
// The `dem:` section of a case file (docs/case-reference.md, "dem"): contact models, species,
// interactions per pair, walls, and how the grains are filled in and settled.
#include <filesystem>
#include <memory>

#include "dem/config.hpp"
#include "dem/insertion.hpp"
#include "geometry/shape.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

// Grains inserted at random into `region`, settled under gravity until their kinetic energy
// per grain falls below `settle_energy` (or `settle_time` passes), then given species 1 on the
// side of the plane its normal points to (species 0 on the other).
struct GrainFill {
  std::shared_ptr<const geometry::Shape> region;
  dem::InsertionRequest insertion;
  double settle_energy = 1.0e-8;  // [J] per grain
  double settle_time = 2.0;       // [s], at most
  Vec3 split_point = Vec3::Zero();
  Vec3 split_normal = Vec3::UnitX();
};

struct DemSpec {
  dem::Config config;
  GrainFill fill;
};

DemSpec read_dem(Reader& root, const std::filesystem::path& case_folder);

}  // namespace partimix::io
