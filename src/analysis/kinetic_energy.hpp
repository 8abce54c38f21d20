#pragma once
// Kinetic energy of the material particles (fluid or grains; translation only): E = sum_i m_i |v_i|^2 / 2.
#include "analysis/analysis.hpp"

namespace partimix::analysis {

class KineticEnergy final : public Analysis {
 public:
  std::vector<Column> columns() const override { return {{"kinetic_energy", "J"}}; }
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
};

}  // namespace partimix::analysis
