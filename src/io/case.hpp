#pragma once
// A case: the typed, validated content of a case file (DESIGN.md, "One run"). Built by
// load_case(); every key, unit and default is listed in docs/case-reference.md.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/bed_options.hpp"
#include "analysis/sampling_cells.hpp"
#include "core/vec.hpp"
#include "geometry/lattice.hpp"
#include "geometry/motion.hpp"
#include "geometry/shape.hpp"
#include "io/dem_section.hpp"
#include "particles/domain.hpp"
#include "sph/config.hpp"
#include "sph/rheology.hpp"

namespace partimix::io {

struct TimeControl {
  double end = 0.0;              // [s]
  double output_interval = 0.0;  // frames every ... [s]
  double sample_interval = 0.0;  // series.csv rows every ... [s]
};

struct FluidRegion {
  std::shared_ptr<const geometry::Shape> shape;
};

// The tracer of the mixing analyses: the fluid on the side of a plane the normal points to, at
// t = 0, gets tag 1 (the rest tag 0): (x - point) . normal > 0.
struct TracerPlane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = -Vec3::UnitY();  // the seed: the fluid at y < 0
};

struct FluidSpec {
  double density = 1000.0;       // rho0 [kg/m^3]
  sph::RheologyConfig rheology;  // from `viscosity` (newtonian) or the `rheology` map
  std::vector<FluidRegion> regions;
  std::optional<TracerPlane> tracer;
};

struct WallSpec {
  std::shared_ptr<const geometry::Shape> shape;
  std::vector<geometry::Face> open_faces;
  geometry::MotionConfig motion;  // prescribed motion of this wall as a body
  bool solid = false;  // true: layers inside the shape (an impeller), not outside (a container)
};

struct OutputSpec {
  bool frames = true;  // VTK frames every output_interval
};

// A measurement sampled into series.csv (docs/case-reference.md, "analyses").
// front_position: the largest coordinate of any fluid particle along `axis` (dam break).
// body_loads, power_number: the load on wall `body` and its power and Reynolds numbers
// (docs/power.md). mixing: uniformity and Lacey indices of the tracer (docs/mixing.md).
// packing_fraction, velocity_profile, angle_of_repose: measurements of a granular bed
// (docs/mixing.md, "Measurements of a granular bed").
struct AnalysisSpec {
  std::string type;
  int axis = 0;
  int body = 0;
  Vec3 vessel_axis_point = Vec3::Zero();
  double average_revolutions = 1.0;
  double diameter = 0.0;
  double metzner_otto = 7.54;
  analysis::MixingRegion mixing;
  analysis::PackingBox packing;    // packing_fraction
  analysis::ProfileLine profile;   // velocity_profile
  analysis::ReposeSection repose;  // angle_of_repose
};

struct Case {
  std::string file;  // path of the case file as given
  std::string name;
  std::string description;
  std::string solver;  // sph | dem
  Domain domain;       // with the number of dimensions
  Vec3 gravity = Vec3::Zero();
  TimeControl time;
  sph::Config sph;
  DemSpec dem;      // solver dem: the grains, their contacts and walls
  FluidSpec fluid;  // solver dem: only the tracer, the split of dem.fill
  std::vector<WallSpec> walls;
  OutputSpec output;
  std::vector<AnalysisSpec> analyses;
  nlohmann::json resolved;  // every key with the value used, defaults and --set included
};

// Reads and validates a case file, applying `overrides` ("a.b.c=value", as from --set) first.
// Throws InputError naming file, line, column and key path on any problem.
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace partimix::io
