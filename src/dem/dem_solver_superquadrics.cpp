// The contacts of superquadric grains in the DEM solver (docs/dem.md, "Superquadric grains"):
// the midway point between two grains (dem/superquadric_contact.hpp), warm-started from the
// pair's history, and the deepest point into a wall (dem/superquadric_wall.hpp). The forces act
// at the contact point, so the normal force turns the grains too.
#include <array>
#include <limits>
#include <optional>

#include "dem/dem_solver.hpp"
#include "dem/superquadric_contact.hpp"
#include "dem/superquadric_wall.hpp"

namespace partimix::dem {

int DemSolver::shaped_pair_loads(std::size_t k, const Vec3& rij, double dt) {
  const auto& x = store_.position();
  const auto& v = store_.velocity();
  const auto& m = store_.mass();
  const auto& omega = *angular_velocity_;
  const std::size_t i = pairs_->first(k);
  const std::size_t j = pairs_->second(k);
  const Vec3 centre_j = x[i] - rij;  // the image of j nearest to i
  // A sphere meeting a superquadric is the superquadric of its radius (made here: rare).
  std::optional<Superquadric> sphere_i;
  std::optional<Superquadric> sphere_j;
  auto shape_of = [&](std::size_t g, std::optional<Superquadric>& sphere) -> const Superquadric& {
    if (const Superquadric* shape = shapes_[(*species_)[g]])
      return *shape;
    return sphere.emplace(Vec3::Constant((*radius_)[g]), 2.0, 2.0);
  };
  PairHistory& history = pairs_->history(k);
  std::optional<MidwayStart> start;
  if (history.mu > 0.0)
    start = MidwayStart{x[i] + history.midway, history.mu};
  const SuperquadricContact found =
      find_contact({&shape_of(i, sphere_i), x[i], orientation(i).toRotationMatrix()},
                   {&shape_of(j, sphere_j), centre_j, orientation(j).toRotationMatrix()}, start);
  const int failures = found.converged ? 0 : 1;
  // The warm start of the next step: kept while Newton runs for the pair (its bounding boxes
  // overlap), touching or not.
  const bool solved = found.converged && found.near;
  history.midway = solved ? Vec3(found.midway - x[i]) : Vec3::Zero();
  history.mu = solved ? found.mu : 0.0;
  if (!found.touching) {
    pairs_->set_touching(k, false);
    return failures;
  }
  Contact c;
  c.normal = -found.normal;
  c.overlap = found.overlap;
  const Vec3 arm_i = found.point - x[i];
  const Vec3 arm_j = found.point - centre_j;
  c.contact_velocity = v[i] + omega[i].cross(arm_i) - v[j] - omega[j].cross(arm_j);
  c.relative_angular_velocity = omega[i] - omega[j];
  const std::size_t pair = (*species_)[i] * config_.species.size() + (*species_)[j];
  const double radius_i = hertz_radius(i);
  const double radius_j = hertz_radius(j);
  c.pair = pair_properties(particle_materials_[pair], radius_i, radius_j, m[i], m[j]);
  c.interaction = &config_.particle_interactions[pair];
  const double inertia_i = 1.4 * m[i] * radius_i * radius_i;
  const double inertia_j = 1.4 * m[j] * radius_j * radius_j;
  c.rolling_inertia = 1.0 / (1.0 / inertia_i + 1.0 / inertia_j);
  const ContactLoad load = load_of(c, history.spring, history.rolling_spring, dt);
  PairLoad& out = pairs_->load(k);
  out.force = load.force;
  out.torque_i = arm_i.cross(load.force) + load.rolling;
  out.torque_j = arm_j.cross(-load.force) - load.rolling;
  pairs_->set_touching(k, true);
  return failures;
}

int DemSolver::shaped_wall_contacts(std::size_t i, std::size_t w, WallTouches& out,
                                    int& failures) const {
  const Vec3& x = store_.position()[i];
  const geometry::RigidPose& pose = walls_[w].pose;
  const Vec3 local = pose.rotation.transpose() * (x - pose.origin) + pose.start_origin;
  const Mat3 body_to_local = pose.rotation.transpose() * orientation(i).toRotationMatrix();
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
