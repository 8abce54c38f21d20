#pragma once
// A measurement on a particle set (DESIGN.md, "One run"): it names its columns (with units)
// for series.csv and fills one value per column from a read-only view of the particles.
#include <span>
#include <string>
#include <vector>

#include "core/registry.hpp"
#include "particles/particle_store.hpp"

namespace partimix::analysis {

struct Column {
  std::string name;
  std::string unit;
};

class Analysis {
 public:
  virtual ~Analysis() = default;
  virtual std::vector<Column> columns() const = 0;
  // Writes columns().size() values into `values`.
  virtual void sample(const ParticleStore& particles, std::span<double> values) const = 0;
};

// Options an analysis may take from the case file.
struct AnalysisOptions {
  int axis = 0;
};

// Analyses a case file may ask for, by name: front_position. (Kinetic energy and the largest
// speed are always sampled.)
const Registry<Analysis, const AnalysisOptions&>& analysis_registry();

}  // namespace partimix::analysis
