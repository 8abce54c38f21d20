#pragma once
// A measurement on a particle set (DESIGN.md, "One run"): it names its columns (with units)
// for series.csv and fills one value per column from a read-only view of the particles at a
// sample time; at the end it may add figures (time averages, final values) to the run summary.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "analysis/bed_options.hpp"
#include "analysis/droplet_options.hpp"
#include "analysis/drum_measures.hpp"
#include "analysis/sampling_cells.hpp"
#include "core/registry.hpp"
#include "geometry/motion.hpp"
#include "materials/flow_scales.hpp"
#include "particles/particle_store.hpp"

namespace partimix::analysis {

// Why figures are unreliable: figure name -> reason (run.json "caveats").
using Caveats = std::map<std::string, std::string>;

struct Column {
  std::string name;
  std::string unit;
};

// The summary figures of a run (run.json "figures" and "figure_units"): name -> value, each
// with its unit ("" for a number without one, written [-] like series.csv).
class Figures {
 public:
  void add(const std::string& name, double value, const std::string& unit) {
    values_[name] = value;
    units_[name] = unit;
  }
  double at(const std::string& name) const { return values_.at(name); }
  const std::string& unit(const std::string& name) const { return units_.at(name); }
  bool contains(const std::string& name) const { return values_.contains(name); }
  bool empty() const { return values_.empty(); }
  std::size_t size() const { return values_.size(); }
  const std::map<std::string, double>& values() const { return values_; }
  const std::map<std::string, std::string>& units() const { return units_; }

 private:
  std::map<std::string, double> values_;
  std::map<std::string, std::string> units_;
};

class Analysis {
 public:
  virtual ~Analysis() = default;
  virtual std::vector<Column> columns() const = 0;
  // Writes columns().size() values into `values`.
  virtual void sample(const ParticleStore& particles, double time, std::span<double> values) = 0;
  // Rebuilds the analysis' history when a run resumes from a checkpoint: called, in order, with
  // the time and the values of every row it sampled before the checkpoint, so that its running
  // figures (time averages, mixing-rate fits, last values) continue as if never stopped. The
  // history of every analysis is a function of its sampled values.
  virtual void replay(double time, std::span<const double> values) = 0;
  // True when sample() reads the field "body_force" (Solver::update_body_forces).
  virtual bool needs_body_forces() const { return false; }
  // Adds the analysis' summary figures for run.json's "figures".
  virtual void add_figures(Figures& /*figures*/) const {}
  // Adds, for each of its figures that is not what it claims to be, why (figure name -> reason):
  // a time average whose window is shorter than asked or takes in the start-up ramp.
  virtual void add_caveats(Caveats& /*caveats*/) const {}
};

// The fluid's scales for Reynolds numbers (docs/power.md): a Newtonian fluid has K = mu, n = 1.
using FlowScales = materials::FlowScales;

// A body as the load analyses see it: its index, its motion and where the vessel axis is.
struct BodyOptions {
  int index = 0;                             // the wall's index in the case
  const geometry::Motion* motion = nullptr;  // its prescribed motion
  geometry::MotionConfig motion_config;      // the motion's settings (axis, speeds)
  Vec3 vessel_axis_point = Vec3::Zero();     // a point of the vessel axis (parallel to the axis)
  double average_revolutions = 1.0;          // summary: mean over the last k revolutions
};

// Options an analysis may take from the case file.
struct AnalysisOptions {
  int axis = 0;  // front_position
  BodyOptions body;
  double diameter = 0.0;       // power_number: impeller diameter d_a (d_R) [m]
  double metzner_otto = 7.54;  // power_number: K of the Metzner-Otto shear rate K N [-]
  FlowScales fluid;
  MixingRegion mixing;               // mixing: the sampling cells
  PackingBox packing;                // packing_fraction
  ProfileLine profile;               // velocity_profile
  ReposeSection repose;              // angle_of_repose
  MassRegion region_mass;            // mass_in_region
  FluxPlane flux;                    // mass_flux
  HeightLine height;                 // height_profile
  OrientationReference orientation;  // orientation_order
  DrumMeasures drum_measures;        // drum_segregation, drum_discharge
  DropletOptions droplet;            // droplet
};

// Analyses a case file may ask for, by name: front_position, body_loads, power_number, mixing,
// packing_fraction, velocity_profile, angle_of_repose, mass_in_region, height_profile,
// orientation_order, drum_segregation, drum_discharge, droplet.
// (Kinetic energy and the largest speed are always sampled.)
const Registry<Analysis, const AnalysisOptions&>& analysis_registry();

}  // namespace partimix::analysis
