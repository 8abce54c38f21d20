#pragma once
// The `dem:` section of a case file (docs/case-reference.md, "dem"): contact models, species,
// interactions per pair, and how the grains are filled in and settled. The walls come from the
// case's shared walls section: each wall's surface, motion and material.
#include <memory>
#include <optional>
#include <string>

#include "dem/config.hpp"
#include "dem/insertion.hpp"
#include "geometry/shape.hpp"
#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::dem {

// Grains inserted at random into `region`, settled under gravity until their kinetic energy
// per grain falls below `settle_energy` (or `settle_time` passes), then given species 1 on the
// side of the plane its normal points to (species 0 on the other).
struct GrainFill {
  std::shared_ptr<const geometry::Shape> region;
  InsertionRequest insertion;
  double settle_energy = 1.0e-8;  // [J] per grain
  double settle_time = 2.0;       // [s], at most
  Vec3 split_point = Vec3::Zero();
  Vec3 split_normal = Vec3::UnitX();
};

class DemSection final : public io::MethodSection {
 public:
  Config config;
  std::optional<GrainFill> fill;  // a random fill, settled; or
  Grains grains;                  // the grains as the case places them (dem/grain_list.hpp)
  std::string grains_key;         // where they were given: "dem.grains" or "dem.grains_file"

  // Species 1 of the split is the tracer.
  bool has_tracer() const override { return config.species.size() >= 2; }
  // A species with a shape of unequal half-axes.
  bool has_grain_axes() const override;
};

// Reads `dem` from the root of a case file, with the walls of `the_case`.
std::shared_ptr<DemSection> read_dem_section(io::Reader& root, const io::Case& the_case);

}  // namespace partimix::dem
