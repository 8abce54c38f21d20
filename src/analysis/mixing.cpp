#include "analysis/mixing.hpp"

namespace partimix::analysis {

Mixing::Mixing(const MixingRegion& region)
    : cells_(make_sampling_cells(region)), min_count_(region.min_count), counts_(*cells_) {}

void Mixing::sample(const ParticleStore& particles, double /*time*/, std::span<double> values) {
  roles_.resize(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      roles_[i] = MixingRole::ignored;
    else
      roles_[i] = particles.tag()[i] == 1 ? MixingRole::tracer : MixingRole::other;
  }
  count_cells(*cells_, particles.position(), roles_, counts_);
  last_xi_ = uniformity_index(counts_);
  last_lacey_ = lacey_index(counts_, min_count_).index;
  values[0] = last_xi_;
  values[1] = last_lacey_;
}

void Mixing::add_figures(std::map<std::string, double>& figures) const {
  figures["xi_final"] = last_xi_;
  figures["lacey_final"] = last_lacey_;
}

}  // namespace partimix::analysis
