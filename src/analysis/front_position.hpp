#pragma once
// Surge front: the largest coordinate along one axis of any material particle, fluid or grain (dam
// break).
#include "analysis/analysis.hpp"

namespace partimix::analysis {

class FrontPosition final : public Analysis {
 public:
  explicit FrontPosition(int axis) : axis_(axis) {}
  std::vector<Column> columns() const override;
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double /*time*/, std::span<const double> /*values*/) override {}

 private:
  int axis_;
};

}  // namespace partimix::analysis
