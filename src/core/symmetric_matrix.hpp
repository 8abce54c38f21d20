#pragma once
// A symmetric 3 x 3 matrix by its six distinct entries. Eigen keeps all nine entries of a
// symmetric matrix (its SelfAdjointView is a view of a full one); the DEM solver reads two such
// matrices per grain for every pair it looks at, so six entries instead of nine are a third less
// memory traffic on the hottest loop (docs/performance.md), and the operations below use the
// symmetry to save arithmetic too.
#include "core/vec.hpp"

namespace partimix {

struct alignas(16) SymMat3 {
  double xx = 0.0;
  double yy = 0.0;
  double zz = 0.0;
  double xy = 0.0;
  double xz = 0.0;
  double yz = 0.0;

  // R diag(d) R^T.
  static SymMat3 rotated_diagonal(const Mat3& r, const Vec3& d) {
    const Mat3 rd = r * d.asDiagonal();
    return {rd.row(0).dot(r.row(0)), rd.row(1).dot(r.row(1)), rd.row(2).dot(r.row(2)),
            rd.row(0).dot(r.row(1)), rd.row(0).dot(r.row(2)), rd.row(1).dot(r.row(2))};
  }

  Vec3 operator*(const Vec3& v) const {
    return {xx * v.x() + xy * v.y() + xz * v.z(), xy * v.x() + yy * v.y() + yz * v.z(),
            xz * v.x() + yz * v.y() + zz * v.z()};
  }

  // v^T S v.
  double quadratic(const Vec3& v) const {
    return xx * v.x() * v.x() + yy * v.y() * v.y() + zz * v.z() * v.z() +
           2.0 * (xy * v.x() * v.y() + xz * v.x() * v.z() + yz * v.y() * v.z());
  }

  // This + s b.
  SymMat3 plus_scaled(double s, const SymMat3& b) const {
    return {xx + s * b.xx, yy + s * b.yy, zz + s * b.zz,
            xy + s * b.xy, xz + s * b.xz, yz + s * b.yz};
  }

  SymMat3 operator-(const SymMat3& b) const {
    return {xx - b.xx, yy - b.yy, zz - b.zz, xy - b.xy, xz - b.xz, yz - b.yz};
  }

  // The inverse by cofactors (the matrix must be regular).
  SymMat3 inverse() const {
    const double c_xx = yy * zz - yz * yz;
    const double c_xy = xz * yz - xy * zz;
    const double c_xz = xy * yz - xz * yy;
    const double r = 1.0 / (xx * c_xx + xy * c_xy + xz * c_xz);
    return {r * c_xx, r * (xx * zz - xz * xz), r * (xx * yy - xy * xy), r * c_xy,
            r * c_xz, r * (xy * xz - xx * yz)};
  }
};

}  // namespace partimix
