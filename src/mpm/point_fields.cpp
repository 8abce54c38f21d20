#include "mpm/point_fields.hpp"

namespace partimix::mpm {

PointFields::PointFields(ParticleStore& store)
    : volume(store.add_scalar("volume", "m^3")),
      density(store.add_scalar("density", "kg/m^3")),
      pressure(store.add_scalar("pressure", "Pa")),
      volumetric_strain(store.add_scalar("volumetric_strain", "-")),
      plastic_strain(store.add_scalar("plastic_strain", "-")),
      inertial_number(store.add_scalar("inertial_number", "-")),
      stress_normal(store.add_vector("stress_normal", "Pa")),
      stress_shear(store.add_vector("stress_shear", "Pa")),
      affine_x(store.add_vector("affine_x", "1/s", false)),
      affine_y(store.add_vector("affine_y", "1/s", false)),
      affine_z(store.add_vector("affine_z", "1/s", false)),
      material(store.add_integer("material", "-")) {}

Mat3 PointFields::stress(std::size_t p) const {
  const Vec3& n = stress_normal.values[p];
  const Vec3& s = stress_shear.values[p];
  Mat3 t;
  t << n.x(), s.x(), s.z(), s.x(), n.y(), s.y(), s.z(), s.y(), n.z();
  return t;
}

void PointFields::set_stress(std::size_t p, const Mat3& t) {
  stress_normal.values[p] = Vec3(t(0, 0), t(1, 1), t(2, 2));
  stress_shear.values[p] =
      Vec3(0.5 * (t(0, 1) + t(1, 0)), 0.5 * (t(1, 2) + t(2, 1)), 0.5 * (t(2, 0) + t(0, 2)));
}

Mat3 PointFields::affine(std::size_t p) const {
  Mat3 c;
  c.row(0) = affine_x.values[p].transpose();
  c.row(1) = affine_y.values[p].transpose();
  c.row(2) = affine_z.values[p].transpose();
  return c;
}

void PointFields::set_affine(std::size_t p, const Mat3& c) {
  affine_x.values[p] = c.row(0).transpose();
  affine_y.values[p] = c.row(1).transpose();
  affine_z.values[p] = c.row(2).transpose();
}

}  // namespace partimix::mpm
