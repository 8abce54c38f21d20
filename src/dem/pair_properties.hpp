#pragma once
// The effective radius, mass and moduli of a contact between two spheres, or a sphere and a
// wall (radius and mass infinite), and the damping factor of a restitution coefficient
// (docs/dem.md, "Effective quantities" and "Normal force").
namespace partimix::dem {

struct Material {
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu
};

// One side of a contact: a sphere, or a wall with radius and mass +infinity.
struct ContactSide {
  Material material;
  double radius = 0.0;  // [m]
  double mass = 0.0;    // [kg]
};

struct PairProperties {
  double radius = 0.0;          // R* [m]
  double mass = 0.0;            // m* [kg]
  double youngs_modulus = 0.0;  // E* [Pa]
  double shear_modulus = 0.0;   // G* [Pa]
  double damping = 0.0;         // beta = -ln e / sqrt(pi^2 + ln^2 e), 0 for e = 1
  // sqrt(4 G* / E*): Hertz-Mindlin's sqrt(k_t / S_n), so its tangential damping is the normal
  // one times this.
  double tangential_damping_scale = 0.0;
};

// The parts of PairProperties that depend on the materials and the restitution alone: computed
// once per pair of species (or species and wall), not per contact.
struct MaterialPair {
  double youngs_modulus = 0.0;            // E*
  double shear_modulus = 0.0;             // G*
  double damping = 0.0;                   // beta
  double tangential_damping_scale = 0.0;  // sqrt(4 G* / E*)
};

// beta of restitution e in (0, 1].
double damping_factor(double restitution);

MaterialPair material_pair(const Material& a, const Material& b, double restitution);

// R* and m* of two sides (radius and mass may be +infinity for a wall) with the material pair.
PairProperties pair_properties(const MaterialPair& materials, double radius_a, double radius_b,
                               double mass_a, double mass_b);
// The same for two grains (finite radii and masses), with fewer divisions.
PairProperties grain_pair_properties(const MaterialPair& materials, double radius_a,
                                     double radius_b, double mass_a, double mass_b);

PairProperties pair_properties(const ContactSide& a, const ContactSide& b, double restitution);

}  // namespace partimix::dem
