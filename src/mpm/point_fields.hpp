#pragma once
// The fields of a material point in the particle store (docs/mpm.md): volume, density, stress
// (its normal and shear components as two vectors), pressure, the elastic volumetric strain,
// the equivalent plastic strain and inertial number, the affine velocity of APIC (three rows,
// not written to frames) and the material's index.
#include <cstdint>

#include "core/vec.hpp"
#include "particles/particle_store.hpp"

namespace partimix::mpm {

class PointFields {
 public:
  explicit PointFields(ParticleStore& store);

  Mat3 stress(std::size_t p) const;
  void set_stress(std::size_t p, const Mat3& stress);
  Mat3 affine(std::size_t p) const;
  void set_affine(std::size_t p, const Mat3& affine);

  Field<double>& volume;
  Field<double>& density;
  Field<double>& pressure;
  Field<double>& volumetric_strain;
  Field<double>& plastic_strain;
  Field<double>& inertial_number;
  Field<Vec3>& stress_normal;  // sigma_xx, sigma_yy, sigma_zz
  Field<Vec3>& stress_shear;   // sigma_xy, sigma_yz, sigma_zx
  Field<Vec3>& affine_x;       // rows of C_p
  Field<Vec3>& affine_y;
  Field<Vec3>& affine_z;
  Field<std::int32_t>& material;
};

}  // namespace partimix::mpm
