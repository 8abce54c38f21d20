#pragma once
// Series of the load of the material on one body (docs/power.md): force, torque about the
// body's own axis and about the vessel axis (components along the motion's axis), the power
// the body gives the material, and the power of its rotation alone, |omega_R Gamma_own| (the
// seed's P = 2 pi N Gamma_z). Columns are prefixed body<k>_; the summary gives their means over
// the last revolutions.
#include "analysis/analysis.hpp"
#include "analysis/time_average.hpp"

namespace partimix::analysis {

class BodyLoads final : public Analysis {
 public:
  explicit BodyLoads(const BodyOptions& body);
  std::vector<Column> columns() const override;
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  bool needs_body_forces() const override { return true; }
  void add_figures(Figures& figures) const override;
  void add_caveats(Caveats& caveats) const override;

 private:
  std::string prefix() const;

  BodyOptions body_;
  ColumnHistory history_;
};

}  // namespace partimix::analysis
