// The contacts of superquadric grains in the DEM solver (docs/dem.md, "Superquadric grains"):
// the midway point between two grains (dem/superquadric_contact.hpp), warm-started from the
// pair's history, and the deepest point into a wall (dem/superquadric_wall.hpp). The forces act
// at the contact point, so the normal force turns the grains too.
#include <array>
#include <limits>
#include <optional>

#include "dem/dem_solver.hpp"
#include "dem/ellipsoid_contact.hpp"
#include "dem/superquadric_contact.hpp"
#include "dem/superquadric_wall.hpp"

namespace partimix::dem {

void DemSolver::update_frames() {
  rotations_.resize(store_.size());
  forms_.resize(store_.size());
#pragma omp parallel for schedule(static) if (parallel(store_.size()))
  for (std::size_t i = 0; i < store_.size(); ++i) {
    rotations_[i] = orientation(i).toRotationMatrix();
    if (const auto& rotor = rotors_[(*species_)[i]])
      (*angular_velocity_)[i] = rotor->angular_velocity(rotations_[i], (*angular_momentum_)[i]);
    if (ellipsoidal(i))
      forms_[i] = ellipsoid_form(rotations_[i], (*half_axes_)[i]);
  }
}

bool DemSolver::ellipsoidal(std::size_t i) const {
  const Superquadric* shape = shapes_[(*species_)[i]];
  return shape == nullptr || shape->is_ellipsoid();
}

double DemSolver::smallest_half_axis(std::size_t i) const {
  const Superquadric* shape = shapes_[(*species_)[i]];
  return shape ? shape->half_axes().minCoeff() : (*radius_)[i];
}

double DemSolver::contact_radius(std::size_t i, const Vec3& arm) const {
  const Superquadric* shape = shapes_[(*species_)[i]];
  if (shape == nullptr)
    return (*radius_)[i];
  if (config_.hertz_radius == HertzRadius::equivalent)  // the default: no need to turn the arm
    return shape->equivalent_radius();
  return dem::hertz_radius(*shape, rotations_[i].transpose() * arm, config_.hertz_radius,
                           config_.curvature_limit);
}

// Two ellipsoids (or spheres) by their contact function (the bounding tests made by the caller),
// warm-started from the pair's history.
SuperquadricContact DemSolver::ellipsoid_contact(std::size_t i, std::size_t j, const Vec3& centre_j,
                                                 const PairHistory& history) const {
  return solve_ellipsoid_contact(
      {store_.position()[i], forms_[i], smallest_half_axis(i)},
      {centre_j, forms_[j], smallest_half_axis(j)},
      history.mu > 0.0F ? std::optional<double>(history.mu) : std::nullopt);
}

// Other pairs by the general midway point (dem/superquadric_contact.hpp), warm-started from the
// pair's history.
SuperquadricContact DemSolver::shaped_contact(std::size_t i, std::size_t j, const Vec3& centre_j,
                                              const PairHistory& history) const {
  const Vec3& centre_i = store_.position()[i];
  // A sphere meeting a blocky grain is the superquadric of its radius (made here: rare).
  std::optional<Superquadric> sphere_i;
  std::optional<Superquadric> sphere_j;
  auto shape_of = [&](std::size_t g, std::optional<Superquadric>& sphere) -> const Superquadric& {
    if (const Superquadric* shape = shapes_[(*species_)[g]])
      return *shape;
    return sphere.emplace(Vec3::Constant((*radius_)[g]), 2.0, 2.0);
  };
  std::optional<MidwayStart> start;
  if (history.mu > 0.0F)
    start = MidwayStart{centre_i + history.midway.cast<double>(), history.mu};
  return find_midway_contact({&shape_of(i, sphere_i), centre_i, rotations_[i]},
                             {&shape_of(j, sphere_j), centre_j, rotations_[j]}, start);
}

int DemSolver::shaped_pair_loads(std::size_t k, const Vec3& rij, double dt) {
  const auto& x = store_.position();
  const auto& v = store_.velocity();
  const auto& m = store_.mass();
  const auto& omega = *angular_velocity_;
  const std::size_t i = pairs_->first(k);
  const std::size_t j = pairs_->second(k);
  const Vec3 centre_j = x[i] - rij;  // the image of j nearest to i
  PairHistory& history = pairs_->history(k);
  const bool ellipsoids = ellipsoidal(i) && ellipsoidal(j);
  if (ellipsoids &&
      apart_along_centre_line(forms_[i].inverse_shape, rij, forms_[j].inverse_shape)) {
    pairs_->set_apart(k);
    pairs_->set_gap(k, centre_line_gap(forms_[i].inverse_shape, rij, forms_[j].inverse_shape));
    return 0;
  }
  const SuperquadricContact found = ellipsoids ? ellipsoid_contact(i, j, centre_j, history)
                                               : shaped_contact(i, j, centre_j, history);
  const int failures = found.converged ? 0 : 1;
  if (!found.touching) {
    pairs_->set_apart(k);
    pairs_->set_gap(k, found.gap);
    return failures;
  }
  // The warm start of the next step, kept while the grains touch: an apart pair keeps none, so
  // skipping it while it is known apart changes nothing (docs/dem.md, "Pairs known apart").
  // Single precision is plenty for a starting point, and keeps the history to one cache line.
  history.midway = found.converged ? Vec3f((found.midway - x[i]).cast<float>()) : Vec3f::Zero();
  history.mu = found.converged ? static_cast<float>(found.mu) : 0.0F;
  Contact c;
  c.normal = -found.normal;
  c.overlap = found.overlap;
  const Vec3 arm_i = found.point - x[i];
  const Vec3 arm_j = found.point - centre_j;
  c.contact_velocity = v[i] + omega[i].cross(arm_i) - v[j] - omega[j].cross(arm_j);
  c.relative_angular_velocity = omega[i] - omega[j];
  const std::size_t pair = (*species_)[i] * config_.species.size() + (*species_)[j];
  const Vec3 to_surface = 0.5 * found.overlap * found.normal;  // X_i = point + to_surface
  c.pair = grain_pair_properties(particle_materials_[pair], contact_radius(i, arm_i + to_surface),
                                 contact_radius(j, arm_j - to_surface), m[i], m[j]);
  c.interaction = &config_.particle_interactions[pair];
  const double radius_i = equivalent_radius(i);
  const double radius_j = equivalent_radius(j);
  const double inertia_i = 1.4 * m[i] * radius_i * radius_i;
  const double inertia_j = 1.4 * m[j] * radius_j * radius_j;
  c.rolling_inertia = inertia_i * inertia_j / (inertia_i + inertia_j);
  const ContactLoad load = load_of(c, history.spring, history.rolling_spring, dt);
  pairs_->deliver(
      k,
      {load.force, arm_i.cross(load.force) + load.rolling, arm_j.cross(-load.force) - load.rolling},
      *force_, *torque_);
  return failures;
}

int DemSolver::shaped_wall_contacts(std::size_t i, std::size_t w, WallTouches& out,
                                    int& failures) const {
  const Vec3& x = store_.position()[i];
  const geometry::RigidPose& pose = walls_[w].pose;
  const Vec3 local = pose.rotation.transpose() * (x - pose.origin) + pose.start_origin;
  const Mat3 body_to_local = pose.rotation.transpose() * rotations_[i];
  std::array<WallContact, geometry::kMaxSurfaceContacts> found;
  const int count = superquadric_wall_contacts(
      *shapes_[(*species_)[i]], local, body_to_local, *walls_[w].surface,
      std::span(found.data(), static_cast<std::size_t>(walls_[w].max_contacts)), failures);
  for (int k = 0; k < count; ++k) {
    WallTouch& touch = out[k];
    touch.normal = pose.rotation * found[k].normal;
    touch.overlap = found[k].overlap;
    const Vec3 point = pose.place(found[k].point);
    touch.arm = point - x;
    touch.contact_velocity =
        store_.velocity()[i] + (*angular_velocity_)[i].cross(touch.arm) - pose.velocity_at(point);
    touch.face = found[k].wall.face;
  }
  return count;
}

}  // namespace partimix::dem
