#pragma once
// The case sections of the SPH method (docs/case-reference.md, "sph" and "fluid"): the solver's
// settings, and the fluid's properties, the regions it starts in and its tracer.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shape.hpp"
#include "io/case.hpp"
#include "io/yaml_reader.hpp"
#include "materials/rheology.hpp"
#include "sph/config.hpp"

namespace partimix::sph {

struct FluidRegion {
  std::shared_ptr<const geometry::Shape> shape;
  // scheme: multi_material: the index in sph.materials of the region's material; -1 otherwise.
  int material = -1;
};

// The tracer of the mixing analyses: the fluid on the side of a plane the normal points to, at
// t = 0, gets tag 1 (the rest tag 0): (x - point) . normal > 0.
struct TracerPlane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = -Vec3::UnitY();  // the seed: the fluid at y < 0
};

struct FluidSpec {
  double density = 1000.0;             // rho0 [kg/m^3]
  materials::RheologyConfig rheology;  // from `viscosity` (newtonian) or the `rheology` map
  std::vector<FluidRegion> regions;
  std::optional<TracerPlane> tracer;
};

class SphSection final : public io::MethodSection {
 public:
  Config config;
  FluidSpec fluid;

  bool has_tracer() const override { return fluid.tracer.has_value(); }
  // None for the multi-material scheme, whose materials have no one density and viscosity.
  std::optional<materials::FlowScales> flow_scales() const override {
    if (config.scheme == "multi_material")
      return std::nullopt;
    return materials::flow_scales(fluid.density, fluid.rheology);
  }
  // sph.materials' names with the multi-material scheme; none otherwise.
  std::vector<std::string> material_names() const override {
    std::vector<std::string> names;
    if (config.scheme == "multi_material") {
      for (const MaterialSpec& material : config.multi_material.materials)
        names.push_back(material.name);
    }
    return names;
  }
  std::optional<double> spacing() const override { return config.spacing; }
};

// Reads `sph` and `fluid` from the root of a case file.
std::shared_ptr<SphSection> read_sph_section(io::Reader& root, const io::Case& the_case);

}  // namespace partimix::sph
