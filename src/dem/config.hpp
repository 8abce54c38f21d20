#pragma once
// The settings of the DEM solver (docs/dem.md; case keys in docs/case-reference.md, "dem").
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "dem/pair_properties.hpp"
#include "dem/superquadric.hpp"
#include "dem/surface_curvature.hpp"
#include "geometry/motion.hpp"
#include "geometry/surface.hpp"

namespace partimix::dem {

struct Species {
  std::string name;
  double density = 2500.0;  // [kg/m^3]
  Material material{1.0e7, 0.3};
  // Every grain of the species has this shape; none: spheres, each of its own radius.
  std::optional<Superquadric> shape;
};

// Restitution and friction of one pair: two species, or a species and the walls.
struct Interaction {
  double restitution = 0.5;       // e
  double friction = 0.5;          // mu_s
  double rolling_friction = 0.0;  // mu_r
};

struct WallConfig {
  std::shared_ptr<const geometry::Surface> surface;  // in the wall's frame at t = 0
  geometry::MotionConfig motion;
  Material material{2.0e11, 0.3};
  // Species a with this wall: interactions[a]; empty: Config::wall_interactions.
  std::vector<Interaction> interactions;
};

struct Config {
  std::string normal_law = "hertz";                    // hertz | linear
  double linear_stiffness = 0.0;                       // k_n of the linear law [N/m]
  std::string rolling_resistance = "none";             // none | constant_torque | elastic_plastic
  double rolling_damping = 0.3;                        // eta_r of elastic_plastic
  bool seed_tangential_cap = false;                    // tangential_cap: seed
  double rayleigh_fraction = 0.2;                      // dt = f t_R
  int sort_interval = 50;                              // steps between sorts by cell
  double neighbour_skin = 0.5;                         // skin of the pair list, in largest radii
  HertzRadius hertz_radius = HertzRadius::equivalent;  // of superquadrics
  double curvature_limit = 10.0;  // curvature radii within [r / limit, limit r]
  std::vector<Species> species;
  // Species a with species b: particle_interactions[a * species.size() + b] (symmetric).
  std::vector<Interaction> particle_interactions;
  std::vector<Interaction> wall_interactions;  // species a with a wall, unless the wall says
  // Species a with wall w: wall_interactions or the wall's own.
  const Interaction& wall_interaction(std::size_t w, std::size_t a) const {
    return walls[w].interactions.empty() ? wall_interactions[a] : walls[w].interactions[a];
  }
  std::vector<WallConfig> walls;
};

// The grains a solver starts from.
struct Grains {
  std::vector<Vec3> position;
  std::vector<double> radius;
  std::vector<int> species;
  std::vector<Vec3> velocity;                   // empty: at rest
  std::vector<Vec3> angular_velocity;           // empty: not spinning
  std::vector<Eigen::Quaterniond> orientation;  // body to world; empty: unturned
};

}  // namespace partimix::dem
