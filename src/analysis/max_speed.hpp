#pragma once
// Largest speed |v| of any material particle (fluid or grain).
#include "analysis/analysis.hpp"

namespace partimix::analysis {

class MaxSpeed final : public Analysis {
 public:
  std::vector<Column> columns() const override { return {{"max_speed", "m/s"}}; }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double /*time*/, std::span<const double> /*values*/) override {}
};

}  // namespace partimix::analysis
