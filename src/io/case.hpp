#pragma once
// A case: the typed, validated content of a case file (DESIGN.md, "One run"). Built by
// load_case(); every key, unit and default is listed in docs/case-reference.md. The case knows
// no concrete method: each method named by `solver` reads its own sections into a
// MethodSection of its own type (io/method_type.hpp), and the walls, the domain, time and
// analyses are shared by all of them.
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/bed_options.hpp"
#include "analysis/droplet_options.hpp"
#include "analysis/drum_measures.hpp"
#include "analysis/sampling_cells.hpp"
#include "core/error.hpp"
#include "core/vec.hpp"
#include "geometry/lattice.hpp"
#include "geometry/motion.hpp"
#include "geometry/shape.hpp"
#include "geometry/surface.hpp"
#include "io/size_limits.hpp"
#include "materials/flow_scales.hpp"
#include "particles/domain.hpp"

namespace partimix::io {

struct TimeControl {
  double end = 0.0;                  // [s]
  double output_interval = 0.0;      // frames every ... [s]
  double sample_interval = 0.0;      // series.csv rows every ... [s]
  double checkpoint_interval = 0.0;  // checkpoints every ... [s]; 0: none (but on Ctrl-C)
  std::optional<double> fixed_dt;    // `dt`: the common step of the methods [s]; else adaptive
};

// What a wall is made of, for the methods that need it (DEM contacts): its elastic constants,
// and restitution and friction coefficients that, when given, hold for every species against
// this wall in place of dem.interactions.
struct WallMaterial {
  double youngs_modulus = 2.0e11;  // [Pa] (steel)
  double poisson_ratio = 0.3;
  std::optional<double> restitution;
  std::optional<double> friction;
  std::optional<double> rolling_friction;
};

// One wall of the shared walls section (docs/case-reference.md, "walls"): a container or a body
// that every method uses in its own way: SPH lays wall particles from the shape, DEM contacts
// the surface. Both are in the wall's frame at t = 0; the motion moves them.
struct WallSpec {
  std::shared_ptr<const geometry::Shape> shape;  // null for a mesh that is not closed
  std::shared_ptr<const geometry::Surface> surface;
  std::vector<geometry::Face> open_faces;
  geometry::MotionConfig motion;  // prescribed motion of this wall as a body
  bool solid = false;  // true: layers inside the shape (an impeller), not outside (a container)
  WallMaterial material;
  // How a grid method (MPM) holds the material at this wall: no_slip, slip or friction (Coulomb,
  // with material.friction); docs/mpm.md, "Walls".
  std::string boundary = "no_slip";
  // Why shape is null, as an error at the wall's `file` key, for the methods that need a shape.
  std::optional<InputError> no_shape;
};

struct OutputSpec {
  bool frames = true;  // VTK frames every output_interval
};

// A measurement sampled into series.csv (docs/case-reference.md, "analyses"), of the particles
// of one method (`method`, the first of `solver` by default).
// front_position: the largest coordinate of any fluid particle along `axis` (dam break).
// body_loads, power_number: the load on wall `body` and its power and Reynolds numbers
// (docs/power.md). mixing: uniformity and Lacey indices of the tracer (docs/mixing.md).
// packing_fraction, velocity_profile, angle_of_repose, mass_in_region, height_profile,
// orientation_order: measurements of a granular bed (docs/mixing.md, "Measurements of a
// granular bed"). droplet: the droplet of the multi-material SPH scheme
// (docs/multi-material-sph.md, "The scheme").
struct AnalysisSpec {
  std::string type;
  std::string key;   // where it is in the case: "analyses[i]"
  std::string name;  // optional: its columns and figures are "<name>.<column>"
  std::string method;
  // Its own schedule (requires a name): rows every sample_interval from sample_from to
  // sample_until into series_<name>.csv, in place of series.csv's rows.
  std::optional<double> sample_interval;                          // [s]
  double sample_from = 0.0;                                       // [s]
  double sample_until = std::numeric_limits<double>::infinity();  // [s]
  int axis = 0;
  int body = 0;
  Vec3 vessel_axis_point = Vec3::Zero();
  double average_revolutions = 1.0;
  double diameter = 0.0;
  double metzner_otto = 7.54;
  analysis::MixingRegion mixing;
  analysis::PackingBox packing;                // packing_fraction
  analysis::ProfileLine profile;               // velocity_profile
  analysis::ReposeSection repose;              // angle_of_repose
  analysis::MassRegion region_mass;            // mass_in_region
  analysis::FluxPlane flux;                    // mass_flux
  analysis::HeightLine height;                 // height_profile
  analysis::OrientationReference orientation;  // orientation_order
  analysis::DrumMeasures drum_measures;        // drum_segregation, drum_discharge
  analysis::DropletOptions droplet;            // droplet
};

// What a method read from its own sections of the case file. Each method derives its own type;
// the analyses ask it only what they need to know of any method's material.
class MethodSection {
 public:
  virtual ~MethodSection() = default;
  // Whether the material carries a tracer (tag 1) for the mixing analyses.
  virtual bool has_tracer() const = 0;
  // The fluid's scales for Reynolds numbers, when the material is a fluid that has them.
  virtual std::optional<materials::FlowScales> flow_scales() const { return std::nullopt; }
  // Whether some grains have an axis, for the orientation order (superquadric grains whose
  // half-axes are not all equal; docs/mixing.md, "Orientation order").
  virtual bool has_grain_axes() const { return false; }
  // The names of the materials, in the order of the index each particle's field `material`
  // holds, for the droplet analysis (sph.materials of sph.scheme: multi_material); empty for a
  // method without them.
  virtual std::vector<std::string> material_names() const { return {}; }
  // The initial particle spacing [m] of a method that lays its particles on a lattice
  // (sph.spacing), for the droplet analysis' default link distance.
  virtual std::optional<double> spacing() const { return std::nullopt; }
};

// One method of the case: its name in the method registry, its sections, and how many steps it
// takes per step of the run's clock (time.sub_steps).
struct MethodSpec {
  std::string name;
  std::shared_ptr<MethodSection> section;
  int sub_steps = 1;
};

// What a coupling read from its item of `couplings` (io/coupling_type.hpp). Each coupling
// derives its own type.
class CouplingSection {
 public:
  virtual ~CouplingSection() = default;
};

// One coupling of the case: its type in the coupling registry, where it was written
// ("couplings[k]") and what it read.
struct CouplingSpec {
  std::string type;
  std::string key;
  std::shared_ptr<CouplingSection> section;
};

struct Case {
  std::string file;  // path of the case file as given
  std::string name;
  std::string description;
  std::vector<MethodSpec> methods;  // from `solver`, in its order
  Domain domain;                    // with the number of dimensions
  Vec3 gravity = Vec3::Zero();
  TimeControl time;
  SizeLimits limits;
  std::vector<WallSpec> walls;
  OutputSpec output;
  std::vector<AnalysisSpec> analyses;
  std::vector<CouplingSpec> couplings;  // from `couplings`, in its order
  nlohmann::json resolved;  // every key with the value used, defaults and --set included
  std::map<std::string, InputLocation> key_locations;  // where each key read was written

  // Where an error about the key at `key_path` points: that key's line and column, else those
  // of the nearest enclosing key that was written (`walls[2]` for `walls[2].material.friction`
  // when the material is all defaults), else the file alone.
  InputLocation locate(const std::string& key_path) const;

  // The method named `name`; nullptr when the case does not run it.
  const MethodSpec* method(const std::string& method_name) const;
  // The section of method `method_name` as its own type T (throws std::logic_error when the case
  // does not run that method or its section is of another type).
  template <class T>
  const T& section(const std::string& method_name) const;
  template <class T>
  T& section(const std::string& method_name) {
    return const_cast<T&>(std::as_const(*this).section<T>(method_name));
  }
  // Whether the case runs exactly one method.
  bool single_method() const { return methods.size() == 1; }
};

// Reads and validates a case file, applying `overrides` ("a.b.c=value", as from --set) first.
// Throws InputError naming file, line, column and key path on any problem.
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {});

template <class T>
const T& Case::section(const std::string& method_name) const {
  const MethodSpec* spec = method(method_name);
  const T* typed = spec ? dynamic_cast<const T*>(spec->section.get()) : nullptr;
  if (typed == nullptr)
    throw std::logic_error("the case has no section of method '" + method_name + "' of that type");
  return *typed;
}

}  // namespace partimix::io
