#include "dem/dem_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <omp.h>
#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/prefetch.hpp"
#include "dem/tangential_contact.hpp"
#include "dem/time_step.hpp"
#include "particles/store_state.hpp"

namespace partimix::dem {

namespace {

InputError config_error(const std::string& key, const std::string& what) {
  return InputError(InputLocation{"", 0, 0, key}, what);
}

double sphere_volume(double radius) {
  return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

// Slots for the wall contacts of one grain: each wall's most contacts (at most the history's
// capacity).
int wall_slots(const std::vector<WallConfig>& walls) {
  std::size_t slots = 0;
  for (const WallConfig& wall : walls)
    slots += static_cast<std::size_t>(wall.surface->max_contacts());
  return static_cast<int>(std::clamp<std::size_t>(slots, 1, ContactHistory::kMaxCapacity));
}

bool any_shaped(const std::vector<const Superquadric*>& shapes) {
  return std::any_of(shapes.begin(), shapes.end(), [](const Superquadric* p) { return p; });
}

// The pose held still: no velocity.
geometry::RigidPose at_rest(geometry::RigidPose pose) {
  pose.velocity = Vec3::Zero();
  pose.angular_velocity = Vec3::Zero();
  return pose;
}

}  // namespace

DemSolver::DemSolver(ParticleStore& store, const Domain& domain, const Config& config,
                     const Vec3& gravity, const Grains& grains)
    : store_(store), domain_(domain), config_(config), gravity_(gravity) {
  normal_law_ = normal_contact_registry().create(config.normal_law,
                                                 NormalLawParameters{config.linear_stiffness});
  if (!normal_law_)
    throw config_error("dem.normal_law", "unknown normal contact law '" + config.normal_law + "'");
  if (config.normal_law == "linear" && !(config.linear_stiffness > 0.0))
    throw config_error("dem.linear_stiffness", "the linear law needs a stiffness > 0");
  rolling_ = rolling_resistance_registry().create(config.rolling_resistance,
                                                  RollingParameters{config.rolling_damping});
  if (!rolling_) {
    throw config_error("dem.rolling_resistance",
                       "unknown rolling resistance model '" + config.rolling_resistance + "'");
  }
  for (const Species& species : config_.species) {
    shapes_.push_back(species.shape ? &*species.shape : nullptr);
    rotors_.emplace_back();
    if (species.shape)
      rotors_.back().emplace(species.density * species.shape->unit_inertia());
  }
  add_fields(grains);
  make_walls();
  compute_time_step();
  largest_radius_ = *std::max_element(radius_->begin(), radius_->end());
  const double skin = config_.neighbour_skin * largest_radius_;
  grid_ = std::make_unique<CellGrid>(domain_, 2.0 * largest_radius_ + skin);
  pairs_ = std::make_unique<PairList>(skin);
  wall_history_ = std::make_unique<ContactHistory>(store_.size(), wall_slots(config_.walls));
  sort_by_cell();
  compute_loads(0.0);
}

void DemSolver::add_fields(const Grains& grains) {
  radius_ = &store_.add_scalar("radius", "m").values;
  species_ = &store_.add_integer("species", "").values;
  angular_velocity_ = &store_.add_vector("angular_velocity", "rad/s").values;
  force_ = &store_.add_vector("contact_force", "N").values;
  torque_ = &store_.add_vector("contact_torque", "N m").values;
  orientation_w_ = &store_.add_scalar("orientation_w", "", false).values;
  orientation_v_ = &store_.add_vector("orientation_v", "", false).values;
  pairs_known_apart_ = any_shaped(shapes_);
  if (any_shaped(shapes_)) {
    angular_momentum_ = &store_.add_vector("angular_momentum", "kg m^2/s", false).values;
    half_axes_ = &store_.add_vector("half_axes", "m").values;
    volume_ = &store_.add_scalar("volume", "m^3", false).values;
  }
  const std::size_t count = grains.position.size();
  if (count == 0)
    throw config_error("dem", "there are no grains");
  store_.resize(count);
  if (any_shaped(shapes_))
    glyphs_ = std::make_unique<GrainGlyphs>(count);
  const int species_count = static_cast<int>(config_.species.size());
  for (std::size_t i = 0; i < count; ++i) {
    const int s = grains.species[i];
    if (s < 0 || s >= species_count)
      throw config_error("dem.species", fmt::format("grain {} has no species {}", i, s));
    store_.id()[i] = static_cast<std::int64_t>(i);
    store_.kind()[i] = static_cast<std::int32_t>(ParticleKind::grain);
    store_.position()[i] = grains.position[i];
    (*radius_)[i] = shapes_[s] ? shapes_[s]->bounding_radius() : grains.radius[i];
    set_orientation(i, grains.orientation.empty() ? Quaternion::Identity()
                                                  : grains.orientation[i].normalized());
    if (!grains.velocity.empty())
      store_.velocity()[i] = grains.velocity[i];
    if (!grains.angular_velocity.empty())
      (*angular_velocity_)[i] = grains.angular_velocity[i];
    (*species_)[i] = s;
    assign_shape(i);
    assign_mass(i);
  }
}

// In runs with superquadrics, grain i's half-axes and true volume (a sphere's: its radius thrice
// and its ball's volume), for the analyses and the frames (docs/dem.md, "Drawing superquadric
// grains in ParaView"; docs/mixing.md, "Packing fraction").
void DemSolver::assign_shape(std::size_t i) {
  if (!half_axes_)
    return;
  const Superquadric* shape = shapes_[(*species_)[i]];
  (*half_axes_)[i] = shape ? shape->half_axes() : Vec3::Constant((*radius_)[i]);
  (*volume_)[i] = shape ? shape->volume() : sphere_volume((*radius_)[i]);
}

// The mass of grain i's species and shape, and for a superquadric its angular momentum from its
// angular velocity.
void DemSolver::assign_mass(std::size_t i) {
  const int s = (*species_)[i];
  const Species& species = config_.species[s];
  store_.mass()[i] =
      species.density * (species.shape ? species.shape->volume() : sphere_volume((*radius_)[i]));
  if (rotors_[s]) {
    (*angular_momentum_)[i] = rotors_[s]->angular_momentum(orientation(i), (*angular_velocity_)[i]);
  } else if (angular_momentum_) {
    (*angular_momentum_)[i] =
        0.4 * store_.mass()[i] * (*radius_)[i] * (*radius_)[i] * (*angular_velocity_)[i];
  }
}

Quaternion DemSolver::orientation(std::size_t i) const {
  const Vec3& v = (*orientation_v_)[i];
  return Quaternion((*orientation_w_)[i], v.x(), v.y(), v.z());
}

void DemSolver::set_orientation(std::size_t i, const Quaternion& q) {
  (*orientation_w_)[i] = q.w();
  (*orientation_v_)[i] = q.vec();
}

double DemSolver::equivalent_radius(std::size_t i) const {
  const Superquadric* shape = shapes_[(*species_)[i]];
  return shape ? shape->equivalent_radius() : (*radius_)[i];
}

void DemSolver::make_walls() {
  const std::size_t n = config_.species.size();
  particle_materials_.resize(n * n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      particle_materials_[a * n + b] =
          material_pair(config_.species[a].material, config_.species[b].material,
                        config_.particle_interactions[a * n + b].restitution);
    }
  }
  for (std::size_t w = 0; w < config_.walls.size(); ++w) {
    const WallConfig& wall = config_.walls[w];
    auto motion = geometry::motion_registry().create(wall.motion.type, wall.motion);
    if (!motion) {
      throw config_error(fmt::format("walls[{}].motion.type", w),
                         "unknown motion '" + wall.motion.type + "'");
    }
    const int max_contacts = std::min(wall.surface->max_contacts(), geometry::kMaxSurfaceContacts);
    walls_.push_back({wall.surface.get(), std::move(motion), {}, max_contacts});
    walls_.back().pose = at_rest(walls_.back().motion->pose(0.0));
    for (std::size_t a = 0; a < n; ++a) {
      wall_materials_.push_back(material_pair(config_.species[a].material, wall.material,
                                              config_.wall_interaction(w, a).restitution));
    }
  }
}

// dt = f min over the grains of t_R (hertz; of a superquadric's smallest half-axis) or f times
// the linear contact time of the lightest.
void DemSolver::compute_time_step() {
  rayleigh_time_ = std::numeric_limits<double>::infinity();
  double lightest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < store_.size(); ++i) {
    const Species& s = config_.species[(*species_)[i]];
    const double size = s.shape ? s.shape->half_axes().minCoeff() : (*radius_)[i];
    rayleigh_time_ = std::min(rayleigh_time_, rayleigh_time(size, s.density, s.material));
    lightest = std::min(lightest, store_.mass()[i]);
  }
  const double scale = config_.normal_law == "linear"
                           ? linear_contact_time(lightest, config_.linear_stiffness)
                           : rayleigh_time_;
  time_step_ = config_.rayleigh_fraction * scale;
}

void DemSolver::step(double dt) {
  kick_and_drift(dt);
  time_ += dt;
  if (++steps_ % config_.sort_interval == 0)
    sort_by_cell();
  for (WallState& wall : walls_)
    wall.pose = walls_frozen_ ? at_rest(wall.motion->pose(0.0)) : wall.motion->pose(time_);
  compute_loads(dt);
#pragma omp parallel for schedule(static) if (parallel(store_.size()))
  for (std::size_t i = 0; i < store_.size(); ++i)
    half_kick(i, dt, true);
}

ExternalForces DemSolver::enable_external_forces() {
  if (!external_.force) {
    external_.force = &store_.add_vector("external_force", "N", false).values;
    external_.drag = &store_.add_scalar("external_drag", "kg/s", false).values;
    external_.impulse = &store_.add_vector("external_impulse", "N s", false).values;
  }
  return external_;
}

// The first half kick and the drift, in one pass over the grains.
void DemSolver::kick_and_drift(double dt) {
#pragma omp parallel for schedule(static) if (parallel(store_.size()))
  for (std::size_t i = 0; i < store_.size(); ++i) {
    half_kick(i, dt, false);
    drift(i, dt);
  }
}

void DemSolver::half_kick(std::size_t i, double dt, bool superquadric_spins) {
  const double m = store_.mass()[i];
  Vec3& v = store_.velocity()[i];
  const Vec3& load = (*force_)[i];
  if (external_.force) {  // the drag backward in time over the half kick (external_forces.hpp)
    const Vec3 turning = external_.spin.cross(store_.position()[i] - external_.axis_point);
    const double drag = (*external_.drag)[i];
    const Vec3 held = (*external_.force)[i] + drag * turning;
    v = (v + 0.5 * dt * ((load + held) / m + gravity_)) / (1.0 + 0.5 * dt * drag / m);
    (*external_.impulse)[i] += 0.5 * dt * (held - drag * v);
  } else {
    v += 0.5 * dt * (load / m + gravity_);
  }
  if (const auto& rotor = rotors_[(*species_)[i]]) {
    kick_angular_momentum((*angular_momentum_)[i], (*torque_)[i], dt);
    if (superquadric_spins)  // the orientation of this step's frames (update_frames)
      (*angular_velocity_)[i] = rotor->angular_velocity(rotations_[i], (*angular_momentum_)[i]);
    return;
  }
  const double inertia = 0.4 * m * (*radius_)[i] * (*radius_)[i];
  (*angular_velocity_)[i] += 0.5 * dt / inertia * (*torque_)[i];
  if (angular_momentum_)  // beside superquadrics, for the analyses
    (*angular_momentum_)[i] = inertia * (*angular_velocity_)[i];
}

// The position, and a superquadric's orientation by the torque-free motion of its rotor
// (dem/rigid_rotation.hpp; its angular velocity follows in update_frames). A sphere's
// orientation is not needed and not kept: it stays the identity (turning it cost a tenth of a
// step). The grain's travel bounds how far its surface moved: |dx| plus, for a turning grain,
// 2 R |q' - q| (docs/dem.md, "Pairs known apart").
void DemSolver::drift(std::size_t i, double dt) {
  Vec3& x = store_.position()[i];
  const Vec3 dx = dt * store_.velocity()[i];
  x += dx;
  domain_.wrap(x);
  double turn = 0.0;
  if (const auto& rotor = rotors_[(*species_)[i]]) {
    const Quaternion before = orientation(i);
    Quaternion q = before;
    rotor->drift(q, (*angular_momentum_)[i], dt);
    set_orientation(i, q);
    turn = 2.0 * (*radius_)[i] * (q.coeffs() - before.coeffs()).norm();
  }
  if (pairs_known_apart_)
    pairs_->add_travel(i, dx.norm() + turn);
}

// Sorts the grains by cell (neighbours near in memory) and lists the pairs again.
void DemSolver::sort_by_cell() {
  grid_->build(store_.position());
  const auto order = grid_->cell_order();
  sort_order_.assign(order.begin(), order.end());
  store_.reorder(sort_order_);
  wall_history_->reorder(sort_order_);
  grid_->build(store_.position());
  pairs_->build(*grid_, store_.position(), *radius_, sort_order_);
}

// Each pair once (in parallel, each writing its own load), then each grain gathers its pairs'
// loads and adds its wall contacts.
void DemSolver::compute_loads(double dt) {
  const auto& x = store_.position();
  if (pairs_->stale(x, domain_)) {
    grid_->build(x);
    pairs_->build(*grid_, x, *radius_);
  }
  if (angular_momentum_)
    update_frames();
  pairs_->partition(parallel(store_.size()) ? omp_get_max_threads() : 1);
  live_pairs_.resize(static_cast<std::size_t>(pairs_->blocks()));
  int failures = 0;
#pragma omp parallel for schedule(static, 1) reduction(+ : failures) if (pairs_->blocks() > 1)
  for (int b = 0; b < pairs_->blocks(); ++b)
    failures += block_loads(b, dt);
  bool overflow = false;
#pragma omp parallel for schedule(static) reduction(|| : overflow) reduction(+ : failures) \
    if (parallel(store_.size()))
  for (std::size_t i = 0; i < store_.size(); ++i) {
    if (pairs_->gathered(i))
      pairs_->gather(i, (*force_)[i], (*torque_)[i]);
    overflow = !wall_loads(i, dt, failures) || overflow;
  }
  contact_failures_ += failures;
  if (overflow) {
    throw RunError(
        fmt::format("a grain touches more than {} wall faces at once (the slots of its "
                    "wall contact history)",
                    wall_history_->capacity()));
  }
}

// Block b's grains start from no load; its pairs in order add theirs.
int DemSolver::block_loads(int b, double dt) {
  const std::uint32_t begin = pairs_->block_start(b);
  const std::uint32_t end = pairs_->block_start(b + 1);
  std::fill(force_->begin() + begin, force_->begin() + end, Vec3::Zero());
  std::fill(torque_->begin() + begin, torque_->begin() + end, Vec3::Zero());
  const std::size_t first = pairs_->pair_start(begin);
  const std::size_t last = pairs_->pair_start(end);
  if (pairs_known_apart_)
    return live_pair_loads(live_pairs_[static_cast<std::size_t>(b)], first, last, dt);
  int failures = 0;
  for (std::size_t k = first; k < last; ++k)
    failures += pair_loads(k, dt);
  return failures;
}

// The pairs [first, last) not known apart, gathered first (into `live`, which keeps its
// memory), then loaded in order with the history and grain j's form of the pair a few ahead
// prefetched: the loop is bound by the wait for them (docs/performance.md, "Fifth session").
// The prefetches stay in the loop's body: moved into a function of their own, GCC judged that
// function free of effects and dropped its calls.
int DemSolver::live_pair_loads(std::vector<std::uint32_t>& live, std::size_t first,
                               std::size_t last, double dt) {
  live.resize(last - first);
  std::size_t count = 0;
  for (std::size_t k = first; k < last; ++k) {
    live[count] = static_cast<std::uint32_t>(k);
    count += pairs_->known_apart(k) ? 0 : 1;
  }
  int failures = 0;
  for (std::size_t n = 0; n < count; ++n) {
    if (n + kPrefetchAhead < count) {
      const std::uint32_t ahead = live[n + kPrefetchAhead];
      prefetch_lines(&pairs_->history(ahead), sizeof(PairHistory));
      prefetch_lines(&forms_[pairs_->second(ahead)], sizeof(EllipsoidForm));
    }
    failures += pair_loads(live[n], dt);
  }
  return failures;
}

int DemSolver::pair_loads(std::size_t k, double dt) {
  const auto& x = store_.position();
  const auto& v = store_.velocity();
  const auto& m = store_.mass();
  const auto& radius = *radius_;
  const auto& omega = *angular_velocity_;
  const std::size_t i = pairs_->first(k);
  const std::size_t j = pairs_->second(k);
  const Vec3 rij = domain_.displacement(x[i], x[j]);
  const double reach = radius[i] + radius[j];
  const double r2 = rij.squaredNorm();
  if (r2 >= reach * reach) {
    pairs_->set_apart(k);
    if (pairs_known_apart_)
      pairs_->set_gap(k, std::sqrt(r2) - reach);
    return 0;
  }
  if (shapes_[(*species_)[i]] || shapes_[(*species_)[j]])
    return shaped_pair_loads(k, rij, dt);
  const double distance = std::sqrt(r2);
  Contact c;
  c.normal = rij * (1.0 / distance);
  c.overlap = reach - distance;
  const double lever_i = radius[i] - 0.5 * c.overlap;
  const double lever_j = radius[j] - 0.5 * c.overlap;
  c.contact_velocity =
      v[i] - v[j] - lever_i * omega[i].cross(c.normal) - lever_j * omega[j].cross(c.normal);
  c.relative_angular_velocity = omega[i] - omega[j];
  const std::size_t pair = (*species_)[i] * config_.species.size() + (*species_)[j];
  c.pair = grain_pair_properties(particle_materials_[pair], radius[i], radius[j], m[i], m[j]);
  c.interaction = &config_.particle_interactions[pair];
  const double inertia_i = 1.4 * m[i] * radius[i] * radius[i];  // about the contact point
  const double inertia_j = 1.4 * m[j] * radius[j] * radius[j];
  c.rolling_inertia = inertia_i * inertia_j / (inertia_i + inertia_j);
  PairHistory& history = pairs_->history(k);
  const ContactLoad load = load_of(c, history.spring, history.rolling_spring, dt);
  pairs_->deliver(k,
                  {load.force, (-lever_i * c.normal).cross(load.tangential) + load.rolling,
                   (-lever_j * c.normal).cross(load.tangential) - load.rolling},
                  *force_, *torque_);
  return 0;
}

// The wall contacts of grain i, one per touching face of each wall; false when its wall
// history has no slot left.
bool DemSolver::wall_loads(std::size_t i, double dt, int& failures) {
  const auto& m = store_.mass();
  const int s_i = (*species_)[i];
  const bool shaped = shapes_[s_i] != nullptr;
  const double radius = equivalent_radius(i);
  std::uint64_t touched = 0;
  bool fits = true;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    WallTouches touches;
    const int count = shaped ? shaped_wall_contacts(i, w, touches, failures)
                             : sphere_wall_contacts(i, w, touches);
    if (count == 0)
      continue;
    WallSlots slots;
    fits = claim_wall_slots(i, w, touches, count, slots, touched) && fits;
    for (int k = 0; k < count; ++k) {
      if (slots[k] < 0)
        continue;
      Contact c;
      c.normal = touches[k].normal;
      c.overlap = touches[k].overlap;
      c.contact_velocity = touches[k].contact_velocity;
      c.relative_angular_velocity = (*angular_velocity_)[i] - walls_[w].pose.angular_velocity;
      // The grain's own surface point: the deepest point into the face (docs/dem.md).
      const double contact =
          shaped ? contact_radius(i, touches[k].arm - 0.5 * c.overlap * c.normal) : radius;
      c.pair = pair_properties(wall_materials_[w * config_.species.size() + s_i], contact,
                               std::numeric_limits<double>::infinity(), m[i],
                               std::numeric_limits<double>::infinity());
      c.interaction = &config_.wall_interaction(w, static_cast<std::size_t>(s_i));
      c.rolling_inertia = 1.4 * m[i] * radius * radius;
      ContactSlot& history = wall_history_->slot(i, slots[k]);
      const ContactLoad load = load_of(c, history.spring, history.rolling_spring, dt);
      (*force_)[i] += load.force;
      // A sphere's normal force passes through its centre.
      (*torque_)[i] += touches[k].arm.cross(shaped ? load.force : load.tangential) + load.rolling;
    }
  }
  wall_history_->retain(i, touched);
  return fits;
}

// A contact on the face it touched last step keeps its slot. A new one takes over the slot, and
// so the springs, of a contact with the same wall that ended this step (the grain moved on from
// one face to the next, as across the triangles of a flat mesh; docs/dem.md, "Walls of several
// faces"), the first such in slot order; so a wall holds no more slots than its most contacts.
bool DemSolver::claim_wall_slots(std::size_t i, std::size_t w, const WallTouches& touches,
                                 int count, WallSlots& slots, std::uint64_t& touched) {
  for (int k = 0; k < count; ++k) {
    slots[k] = wall_history_->find(i, ContactHistory::wall_partner(w, touches[k].face));
    if (slots[k] >= 0)
      touched |= std::uint64_t{1} << slots[k];
  }
  bool fits = true;
  for (int k = 0; k < count; ++k) {
    if (slots[k] >= 0)
      continue;
    const std::int64_t partner = ContactHistory::wall_partner(w, touches[k].face);
    slots[k] = ended_wall_slot(i, w, touched);
    if (slots[k] >= 0)
      wall_history_->slot(i, slots[k]).partner = partner;
    else
      slots[k] = wall_history_->find_or_add(i, partner);
    if (slots[k] < 0)
      fits = false;
    else
      touched |= std::uint64_t{1} << slots[k];
  }
  return fits;
}

// The first slot of grain i with wall w not touched this step; -1 when there is none.
int DemSolver::ended_wall_slot(std::size_t i, std::size_t w, std::uint64_t touched) const {
  for (int k = 0; k < wall_history_->count(i); ++k) {
    const std::int64_t partner = wall_history_->slot(i, k).partner;
    if (!((touched >> k) & 1U) && partner < 0 && ContactHistory::wall_of(partner) == w)
      return k;
  }
  return -1;
}

// Sphere i against the faces of wall w.
int DemSolver::sphere_wall_contacts(std::size_t i, std::size_t w, WallTouches& out) const {
  const Vec3& x = store_.position()[i];
  const double radius = (*radius_)[i];
  const geometry::RigidPose& pose = walls_[w].pose;
  const Vec3 local = pose.rotation.transpose() * (x - pose.origin) + pose.start_origin;
  std::array<geometry::SurfacePoint, geometry::kMaxSurfaceContacts> points;
  const int found = walls_[w].surface->contacts(
      local, radius, std::span(points.data(), static_cast<std::size_t>(walls_[w].max_contacts)));
  int count = 0;
  for (int k = 0; k < found; ++k) {
    const geometry::SurfacePoint& surface = points[k];
    if (surface.gap >= radius)
      continue;
    WallTouch& touch = out[count++];
    touch.normal = pose.rotation * surface.normal;
    touch.overlap = radius - surface.gap;
    const Vec3 point = pose.place(surface.point);
    const double lever = radius - 0.5 * touch.overlap;
    touch.contact_velocity = store_.velocity()[i] - pose.velocity_at(point) -
                             lever * (*angular_velocity_)[i].cross(touch.normal);
    touch.arm = -lever * touch.normal;
    touch.face = surface.face;
  }
  return count;
}

// The normal, tangential and rolling loads of one contact on particle i (docs/dem.md).
DemSolver::ContactLoad DemSolver::load_of(const Contact& c, Vec3& spring, Vec3& rolling_spring,
                                          double dt) const {
  const double u_n = c.contact_velocity.dot(c.normal);
  const NormalResponse normal = normal_law_->respond(c.pair, c.overlap, u_n);
  const double normal_force = normal.force;
  const Interaction& with = *c.interaction;
  TangentialStep tangential{normal.tangential_stiffness,
                            normal.tangential_damping,
                            normal_force,
                            c.normal,
                            c.contact_velocity - u_n * c.normal,
                            with.friction,
                            dt};
  if (config_.seed_tangential_cap)
    tangential.spring_cap = seed_spring_cap(c.pair, with.friction, c.overlap);
  const Vec3 f_t = tangential_force(tangential, spring);
  const RollingStep rolling{
      normal_force, normal.normal_stiffness,     c.pair.radius,         c.rolling_inertia,
      c.normal,     c.relative_angular_velocity, with.rolling_friction, dt};
  return {normal_force * c.normal + f_t, f_t, rolling_->torque(rolling, rolling_spring)};
}

void DemSolver::set_species(std::size_t i, int species) {
  (*species_)[i] = species;
  store_.tag()[i] = species;
  assign_shape(i);
  assign_mass(i);
}

std::vector<FrameArray> DemSolver::frame_arrays() {
  if (!glyphs_)
    return {};
  return glyphs_->update(store_, shapes_);
}

void DemSolver::record_settling(double time, double kinetic_energy_per_grain) {
  settle_time_ = time;
  settle_energy_ = kinetic_energy_per_grain;
}

std::map<std::string, double> DemSolver::derived_parameters() const {
  return {{"settle_time [s]", settle_time_},
          {"settle_kinetic_energy_per_grain [J]", settle_energy_},
          {"rayleigh_time [s]", rayleigh_time_},
          {"time_step [s]", time_step_},
          {"largest_radius [m]", largest_radius_},
          {"neighbour_skin [m]", pairs_->skin()},
          {"contact_detection_failures [-]", static_cast<double>(contact_failures_)}};
}

// Not saved: the walls' poses (each step sets them from the time before it uses them) and the
// time step (the constructor derives it from the grains, which the same case makes again).
void DemSolver::save(StateArchive& archive, const std::string& prefix) const {
  save_store(store_, archive, prefix);
  pairs_->save(archive, prefix + "pairs/", store_.id());
  wall_history_->save(archive, prefix + "wall_contacts/");
  archive.put_scalar(prefix + "time", time_);
  archive.put_integers(prefix + "steps",
                       std::vector<std::int64_t>{steps_, walls_frozen_ ? 1 : 0, contact_failures_});
  archive.put_doubles(prefix + "settling", std::vector<double>{settle_time_, settle_energy_});
}

void DemSolver::restore(const StateArchive& archive, const std::string& prefix) {
  restore_store(store_, archive, prefix);
  const auto species_count = static_cast<std::int32_t>(config_.species.size());
  for (const std::int32_t s : *species_) {
    if (s < 0 || s >= species_count)
      throw StateError(fmt::format("{}fields/species: a grain of species {}, the case has {}",
                                   prefix, s, species_count));
  }
  wall_history_->restore(archive, prefix + "wall_contacts/");
  grid_->build(store_.position());
  pairs_->restore(archive, prefix + "pairs/", *grid_, store_.position(), *radius_, store_.id());
  const auto steps = archive.integers(prefix + "steps");
  const auto settling = archive.doubles(prefix + "settling");
  if (steps.size() != 3 || settling.size() != 2)
    throw StateError(prefix + ": the steps or settling entries have the wrong size");
  time_ = archive.scalar(prefix + "time");
  steps_ = steps[0];
  walls_frozen_ = steps[1] != 0;
  contact_failures_ = steps[2];
  settle_time_ = settling[0];
  settle_energy_ = settling[1];
}

double DemSolver::mean_contacts() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < store_.size(); ++i)
    sum += pairs_->contacts(i) + wall_history_->count(i);
  return sum / static_cast<double>(store_.size());
}

std::size_t DemSolver::bytes() const {
  std::size_t live = 0;
  for (const auto& pairs : live_pairs_)
    live += pairs.capacity() * sizeof(std::uint32_t);
  return store_.bytes() + grid_->bytes() + pairs_->bytes() + wall_history_->bytes() +
         rotations_.capacity() * sizeof(Mat3) + forms_.capacity() * sizeof(EllipsoidForm) + live;
}

}  // namespace partimix::dem
