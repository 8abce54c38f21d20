#pragma once
// Kinetic energy of the material particles (fluid or grains): translation,
// E = sum_i m_i |v_i|^2 / 2, and, for grains that carry the fields "radius" and
// "angular_velocity" (DEM), rotation of solid spheres, E_rot = sum_i (1/5) m_i R_i^2 |w_i|^2
// (I = (2/5) m R^2). Whether the rotational column exists is decided at set-up from the fields of
// the store, so SPH output (no radius field) keeps its one column.
#include "analysis/analysis.hpp"

namespace partimix::analysis {

class KineticEnergy final : public Analysis {
 public:
  // Translation only.
  KineticEnergy() = default;
  // Adds the column rotational_energy when `particles` has the scalar field "radius" and the
  // vector field "angular_velocity".
  explicit KineticEnergy(const ParticleStore& particles);

  std::vector<Column> columns() const override;
  // The rotational column is NaN for a store that lacks either field.
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double /*time*/, std::span<const double> /*values*/) override {}
  bool rotational() const { return rotational_; }

 private:
  bool rotational_ = false;
};

// True when `particles` has the fields the rotational energy needs.
bool has_rotation_fields(const ParticleStore& particles);

}  // namespace partimix::analysis
