#pragma once
// The tangential force of a contact (docs/dem.md, "Tangential force"): an incremental spring
// with history (Mindlin 1949; Di Renzo and Di Maio 2004), carried into the current contact
// plane each step and capped by Coulomb friction on the compressive normal force.
#include <limits>

#include "core/vec.hpp"
#include "dem/pair_properties.hpp"

namespace partimix::dem {

struct TangentialStep {
  double stiffness = 0.0;     // k_t [N/m] (NormalResponse::tangential_stiffness)
  double damping = 0.0;       // c_t [N s/m] (NormalResponse::tangential_damping)
  double normal_force = 0.0;  // F_n [N], positive repulsive
  Vec3 normal = Vec3::UnitZ();
  Vec3 tangential_velocity = Vec3::Zero();  // v_t of the contact point, in the contact plane
  double friction = 0.0;                    // mu_s
  double dt = 0.0;
  // The seed's cap on |xi| (tangential_cap: seed): mu_s E* / (4 G*) overlap; infinite: none.
  double spring_cap = std::numeric_limits<double>::infinity();
};

// mu_s E* / (4 G*) overlap: Mindlin's tangential displacement at full sliding, the seed's
// delta_t,max = mu_s (2 - nu) / (2 (1 - nu)) overlap for one material.
double seed_spring_cap(const PairProperties& pair, double friction, double overlap);

// Updates the spring xi of the contact (its history) and returns the tangential force on
// particle i: the trial force -k_t xi - c_t v_t (c_t from the normal law: 2 sqrt(5/6) beta
// sqrt(k_t m*)), while it
// is within mu_s max(F_n, 0) (sticking); otherwise (sliding) the trial force scaled to that
// size, carried by the spring alone: xi = -F_t / k_t.
Vec3 tangential_force(const TangentialStep& step, Vec3& spring);

}  // namespace partimix::dem
