#pragma once
// The solid volume of each grain (area when flat), for the analyses that weigh grains by it: the
// grain's `volume` where the particles carry it (superquadrics), else the ball (in 2D the disc)
// of its `radius`; and the grains' species.
#include <cstddef>
#include <string>

#include "particles/particle_store.hpp"

namespace partimix::analysis {

class GrainVolumes {
 public:
  // Throws RunError naming `analysis` when the particles carry neither field (not grains).
  GrainVolumes(const ParticleStore& particles, const std::string& analysis, bool flat = false);
  double operator()(std::size_t i) const;

 private:
  const Field<double>* volume_;
  const Field<double>* radius_;
  bool flat_;
};

// The grains' `species` field; throws RunError naming `analysis` when the particles have none.
const Field<std::int32_t>& grain_species(const ParticleStore& particles,
                                         const std::string& analysis);

}  // namespace partimix::analysis
