#pragma once
// The per-particle arrays of the SPH solver, held in the particle store (so that sorting and
// writers see them) and referenced here for the interaction loops.
#include <vector>

#include "particles/particle_store.hpp"

namespace partimix::sph {

// A field of the store by name, or null when the store has none (bodies, solid walls and surface
// normals exist only where the particles were generated from a case's walls).
inline const std::vector<double>* scalars_of(const ParticleStore& store, const std::string& name) {
  const Field<double>* field = store.find_scalar(name);
  return field != nullptr ? &field->values : nullptr;
}

inline const std::vector<Vec3>* vectors_of(const ParticleStore& store, const std::string& name) {
  const Field<Vec3>* field = store.find_vector(name);
  return field != nullptr ? &field->values : nullptr;
}

inline const std::vector<std::int32_t>* integers_of(const ParticleStore& store,
                                                    const std::string& name) {
  const Field<std::int32_t>* field = store.find_integer(name);
  return field != nullptr ? &field->values : nullptr;
}

struct Fields {
  explicit Fields(ParticleStore& store)
      : kind(store.kind()),
        position(store.position()),
        velocity(store.velocity()),
        mass(store.mass()),
        density(store.add_scalar("density", "kg/m^3").values),
        pressure(store.add_scalar("pressure", "Pa").values),
        density_rate(store.add_scalar("density_rate", "kg/(m^3 s)", false).values),
        acceleration(store.add_vector("acceleration", "m/s^2", false).values),
        wall_velocity(store.add_vector("wall_velocity", "m/s", false).values),
        ghost_weight(store.add_scalar("ghost_weight", "m^d", false).values),
        viscosity(store.add_scalar("viscosity", "Pa s").values),
        shear_rate(store.add_scalar("shear_rate", "1/s").values),
        angular_velocity(vectors_of(store, "angular_velocity")),
        body_acceleration(vectors_of(store, "body_acceleration")),
        body(integers_of(store, "body")),
        solid(integers_of(store, "solid")),
        surface_depth(scalars_of(store, "surface_depth")),
        surface_normal(vectors_of(store, "surface_normal")) {}

  std::vector<std::int32_t>& kind;
  std::vector<Vec3>& position;
  std::vector<Vec3>& velocity;
  std::vector<double>& mass;
  std::vector<double>& density;
  std::vector<double>& pressure;
  std::vector<double>& density_rate;
  std::vector<Vec3>& acceleration;
  std::vector<Vec3>& wall_velocity;  // wall particles: the no-slip ghost velocity (sph/wall_state)
  // Wall particles: beta_w / sum_f W_wf, so that a fluid particle f's velocity enters the ghost
  // velocity as -ghost_weight W_wf u_f (sph/wall_state.hpp); 0 for walls that see no fluid.
  std::vector<double>& ghost_weight;
  std::vector<double>& viscosity;   // apparent viscosity eta_a of fluid particles
  std::vector<double>& shear_rate;  // gamma_dot of fluid particles
  // Wall particles of moving bodies: the body's angular velocity (geometry/moving_bodies.hpp);
  // null when the store has no bodies.
  const std::vector<Vec3>* angular_velocity;
  const std::vector<Vec3>* body_acceleration;  // of moving wall particles; null without bodies
  const std::vector<std::int32_t>* body;       // each wall particle's body; null without bodies
  // 1 for the particles of a solid body (sph/particle_generation.cpp); null when the particles
  // were not generated from a case's walls.
  const std::vector<std::int32_t>* solid;
  // Wall particles: depth below the wall's surface and its unit normal towards the fluid (zero
  // where unknown), for the extrapolated ghost velocity (sph/particle_generation.cpp); null when
  // the particles were not generated from a case's walls.
  const std::vector<double>* surface_depth;
  const std::vector<Vec3>* surface_normal;
  // Viscous stress tau = 2 eta_a S of every particle, for the stress-form viscous operator only
  // (empty otherwise). Recomputed at every interaction, so it is not part of the store.
  std::vector<Mat3> viscous_stress;
  // sph.smoothing_length: variable only (empty otherwise): each fluid particle's h / h_i and
  // (h / h_i)^(d+1), h the reference smoothing length, from its density at every interaction
  // (docs/sph.md, "Variable smoothing length"). Not part of the store, like viscous_stress.
  std::vector<double> kernel_scale;
  std::vector<double> gradient_scale;
};

inline bool is_fluid(std::int32_t kind) {
  return kind == static_cast<std::int32_t>(ParticleKind::fluid);
}

}  // namespace partimix::sph
