#pragma once
// A case: the typed, validated content of a case file (DESIGN.md, "One run"). Built by
// load_case(); every key, unit and default is listed in docs/case-reference.md.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/vec.hpp"
#include "geometry/lattice.hpp"
#include "geometry/motion.hpp"
#include "geometry/shape.hpp"
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

struct FluidSpec {
  double density = 1000.0;       // rho0 [kg/m^3]
  sph::RheologyConfig rheology;  // from `viscosity` (newtonian) or the `rheology` map
  std::vector<FluidRegion> regions;
};

struct WallSpec {
  std::shared_ptr<const geometry::Shape> shape;
  std::vector<geometry::Face> open_faces;
  geometry::MotionConfig motion;  // prescribed motion of this wall as a body
};

struct OutputSpec {
  bool frames = true;  // VTK frames every output_interval
};

// A measurement sampled into series.csv. front_position: the largest coordinate of any fluid
// particle along `axis` (the surge front of a dam break).
struct AnalysisSpec {
  std::string type;
  int axis = 0;
};

struct Case {
  std::string file;  // path of the case file as given
  std::string name;
  std::string description;
  std::string solver;  // sph
  Domain domain;       // with the number of dimensions
  Vec3 gravity = Vec3::Zero();
  TimeControl time;
  sph::Config sph;
  FluidSpec fluid;
  std::vector<WallSpec> walls;
  OutputSpec output;
  std::vector<AnalysisSpec> analyses;
  nlohmann::json resolved;  // every key with the value used, defaults and --set included
};

// Reads and validates a case file, applying `overrides` ("a.b.c=value", as from --set) first.
// Throws InputError naming file, line, column and key path on any problem.
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace partimix::io
