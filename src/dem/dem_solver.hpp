#pragma once
// DEM for spheres and superquadrics (docs/dem.md): Hertz-Mindlin (or linear) contacts with
// history, rolling resistance, moving walls, periodic axes, velocity Verlet at a fraction of the
// Rayleigh time; superquadric grains turn as rigid bodies with three principal moments.
// Each pair of grains is evaluated once from a neighbour list with a skin, each grain summing
// its pairs' loads in a fixed order (DESIGN.md, "Data and speed"; dem/pair_list.hpp), so the
// result does not depend on the thread count.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dem/config.hpp"
#include "dem/contact_history.hpp"
#include "dem/ellipsoid_contact.hpp"
#include "dem/external_forces.hpp"
#include "dem/grain_glyphs.hpp"
#include "dem/normal_contact.hpp"
#include "dem/pair_list.hpp"
#include "dem/rigid_rotation.hpp"
#include "dem/rolling_resistance.hpp"
#include "geometry/motion.hpp"
#include "geometry/surface.hpp"
#include "particles/cell_grid.hpp"
#include "particles/solver.hpp"

namespace partimix::dem {

class DemSolver final : public Solver {
 public:
  // Fills `store` (empty) with `grains` as particles of kind grain, adds the fields radius,
  // species, angular_velocity, force, torque and the orientation quaternion (and, when a
  // species has a shape, angular_momentum, half_axes and volume), and sets the masses from the
  // species' densities. Throws InputError (key path "dem...") when the configuration cannot be
  // used.
  DemSolver(ParticleStore& store, const Domain& domain, const Config& config, const Vec3& gravity,
            const Grains& grains);

  std::string_view name() const override { return "dem"; }
  const ParticleStore& particles() const override { return store_; }
  const Domain& domain() const override { return domain_; }
  double stable_dt() const override { return time_step_; }
  void step(double dt) override;
  std::map<std::string, double> derived_parameters() const override;
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;
  // With superquadric species, the grains' glyph arrays for ParaView (dem/grain_glyphs.hpp);
  // none for spheres only.
  std::vector<FrameArray> frame_arrays() override;

  // Adds the fields of the external forces (dem/external_forces.hpp), zero, and applies them
  // from the next step on; returns them for the caller to set and read. Call at set-up, before
  // a restore.
  ExternalForces enable_external_forces();
  // The rigid rotation Ω × (x - a) in the external forces' drag (dem/external_forces.hpp).
  void set_external_rotation(const Vec3& spin, const Vec3& axis_point) {
    external_.spin = spin;
    external_.axis_point = axis_point;
  }

  // While frozen the walls stay where their motions put them at t = 0 (settling).
  void freeze_walls(bool frozen) { walls_frozen_ = frozen; }
  // The walls' motions start over at t = 0 (after settling, before the run proper).
  void reset_time() { time_ = 0.0; }
  double time() const { return time_; }
  // Gives grain i species s (and the same tag, so species 1 is the mixing tracer), with the
  // mass of its density.
  void set_species(std::size_t i, int species);
  // Records the settling before the run (for run.json).
  void record_settling(double time, double kinetic_energy_per_grain);
  std::size_t bytes() const;
  // Contacts (with grains and walls) per grain, at the last step.
  double mean_contacts() const;

 private:
  struct WallState {
    const geometry::Surface* surface = nullptr;
    std::unique_ptr<geometry::Motion> motion;
    geometry::RigidPose pose;
    int max_contacts = 1;  // per grain, at most geometry::kMaxSurfaceContacts
  };
  // One contact as particle i sees it: unit normal n from the partner to i, overlap, the
  // relative velocity of the contact point, and the pair's properties.
  struct Contact {
    Vec3 normal = Vec3::Zero();
    double overlap = 0.0;
    Vec3 contact_velocity = Vec3::Zero();
    Vec3 relative_angular_velocity = Vec3::Zero();
    PairProperties pair;
    const Interaction* interaction = nullptr;
    double rolling_inertia = 0.0;
  };
  // The load of one contact on particle i: the force, its tangential part and the rolling
  // torque (for the torques about each centre).
  struct ContactLoad {
    Vec3 force;
    Vec3 tangential;
    Vec3 rolling;
  };
  // A grain's contact with one face of a wall: the unit normal from the wall to the grain, the
  // overlap, the relative velocity of the contact point, the arm from the centre to it and the
  // face. No initialisers: a step fills an array of them per wall and grain.
  struct WallTouch {
    Vec3 normal;
    double overlap;
    Vec3 contact_velocity;
    Vec3 arm;
    int face;
  };
  using WallTouches = std::array<WallTouch, geometry::kMaxSurfaceContacts>;
  using WallSlots = std::array<int, geometry::kMaxSurfaceContacts>;

  void add_fields(const Grains& grains);
  void assign_mass(std::size_t i);
  void assign_shape(std::size_t i);
  void make_walls();
  void compute_time_step();
  // Grain i's v and omega (spheres) or L (superquadrics) by dt/2 of the loads; a
  // superquadric's omega from L too when `superquadric_spins` (not before the drift, which
  // turns it).
  void half_kick(std::size_t i, double dt, bool superquadric_spins);
  void drift(std::size_t i, double dt);
  void kick_and_drift(double dt);
  void sort_by_cell();
  void compute_loads(double dt);
  // The pair loads of block b of the pair list, and of pair k; the number of contact detections
  // that missed their tolerance (superquadrics, dem_solver_superquadrics.cpp).
  int block_loads(int b, double dt);
  int live_pair_loads(std::vector<std::uint32_t>& live, std::size_t first, std::size_t last,
                      double dt);
  int pair_loads(std::size_t k, double dt);
  int shaped_pair_loads(std::size_t k, const Vec3& rij, double dt);
  SuperquadricContact ellipsoid_contact(std::size_t i, std::size_t j, const Vec3& centre_j,
                                        const PairHistory& history) const;
  SuperquadricContact shaped_contact(std::size_t i, std::size_t j, const Vec3& centre_j,
                                     const PairHistory& history) const;
  bool wall_loads(std::size_t i, double dt, int& failures);
  // Grain i against the faces of wall w: per touching face the normal, overlap, velocity of the
  // contact point and the arm from the centre to it; returns their number.
  int sphere_wall_contacts(std::size_t i, std::size_t w, WallTouches& out) const;
  int shaped_wall_contacts(std::size_t i, std::size_t w, WallTouches& out, int& failures) const;
  // The history slots of grain i's `count` contacts with wall w (-1 where none is left), their
  // bits set in `touched`; false when a slot was missing.
  bool claim_wall_slots(std::size_t i, std::size_t w, const WallTouches& touches, int count,
                        WallSlots& slots, std::uint64_t& touched);
  int ended_wall_slot(std::size_t i, std::size_t w, std::uint64_t touched) const;
  // A shaped run's grain frames, set from the orientations before each step's contacts: the
  // rotation (body to world) and, for spheres and ellipsoids, the inverse shape matrix of their
  // contact function (dem/ellipsoid_contact.hpp); the superquadrics' omega from L with it.
  void update_frames();
  bool ellipsoidal(std::size_t i) const;  // a sphere or an ellipsoid
  double smallest_half_axis(std::size_t i) const;
  // The grain's radius, or its shape's volume-equivalent radius (the rolling inertia's).
  double equivalent_radius(std::size_t i) const;
  // Grain i's radius in the Hertz law at its surface point centre + arm (world frame): its
  // radius or its shape's by dem.hertz_radius (docs/dem.md, "Hertz radius").
  double contact_radius(std::size_t i, const Vec3& arm) const;
  Quaternion orientation(std::size_t i) const;
  void set_orientation(std::size_t i, const Quaternion& q);
  ContactLoad load_of(const Contact& contact, Vec3& spring, Vec3& rolling_spring, double dt) const;

  ParticleStore& store_;
  Domain domain_;
  Config config_;
  Vec3 gravity_;
  std::unique_ptr<NormalContactLaw> normal_law_;
  std::unique_ptr<RollingResistance> rolling_;
  std::vector<MaterialPair> particle_materials_;  // by species pair, as the interactions
  std::vector<MaterialPair> wall_materials_;      // by wall * species + species
  std::vector<WallState> walls_;
  std::vector<double>* radius_ = nullptr;
  std::vector<std::int32_t>* species_ = nullptr;
  std::vector<Vec3>* angular_velocity_ = nullptr;
  std::vector<Vec3>* force_ = nullptr;
  std::vector<Vec3>* torque_ = nullptr;
  ExternalForces external_;  // null fields: none
  std::vector<double>* orientation_w_ = nullptr;
  std::vector<Vec3>* orientation_v_ = nullptr;
  // Per species: its shape (null: spheres) and the rotor of its principal moments.
  std::vector<const Superquadric*> shapes_;
  std::vector<std::optional<RigidRotor>> rotors_;
  // Runs with superquadrics skip the pairs known apart (docs/dem.md, "Pairs known apart"); for
  // spheres alone the bookkeeping costs more than it saves (measured 7% slower on bench/'s drum).
  bool pairs_known_apart_ = false;
  static constexpr std::size_t kPrefetchAhead = 8;      // pairs
  std::vector<std::vector<std::uint32_t>> live_pairs_;  // per block: its pairs not known apart
  std::vector<Vec3>* angular_momentum_ = nullptr;       // world frame; runs with superquadrics only
  std::vector<Vec3>* half_axes_ = nullptr;              // body frame; runs with superquadrics only
  std::vector<double>* volume_ = nullptr;               // runs with superquadrics only
  std::unique_ptr<GrainGlyphs> glyphs_;                 // runs with superquadrics only
  // Runs with superquadrics only: each grain's rotation, and the form of each sphere and
  // ellipsoid (dem/ellipsoid_contact.hpp), apart so that a pair of ellipsoids reads 96 bytes
  // of each grain (update_frames).
  std::vector<Mat3> rotations_;
  std::vector<EllipsoidForm> forms_;
  std::int64_t contact_failures_ =
      0;  // contact detections that missed their tolerance, in all steps
  std::unique_ptr<CellGrid> grid_;
  std::unique_ptr<PairList> pairs_;
  std::unique_ptr<ContactHistory> wall_history_;
  std::vector<std::uint32_t> sort_order_;
  double largest_radius_ = 0.0;
  double rayleigh_time_ = 0.0;
  double time_step_ = 0.0;
  double time_ = 0.0;
  long steps_ = 0;
  bool walls_frozen_ = false;
  double settle_time_ = 0.0;
  double settle_energy_ = 0.0;
};

}  // namespace partimix::dem
