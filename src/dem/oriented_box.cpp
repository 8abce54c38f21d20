#include "dem/oriented_box.hpp"

#include <cmath>

namespace partimix::dem {
namespace {

// Added to |R| so that the cross products of nearly parallel edges (near-zero axes) cannot
// report a separation that round-off made up.
constexpr double kParallel = 1e-9;

}  // namespace

// In a's frame: b's axes are the columns of R = A^T B, the centres' offset is t. On each axis L,
// the boxes are separated when |t . L| exceeds the sum of their projected radii.
bool boxes_overlap(const OrientedBox& a, const OrientedBox& b) {
  const Mat3 r = a.rotation.transpose() * b.rotation;
  const Mat3 abs_r = r.cwiseAbs().array() + kParallel;
  const Vec3 t = a.rotation.transpose() * (b.centre - a.centre);
  const Vec3& ea = a.half_extents;
  const Vec3& eb = b.half_extents;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(t[k]) > ea[k] + abs_r.row(k).dot(eb))
      return false;
    if (std::abs(t.dot(r.col(k))) > abs_r.col(k).dot(ea) + eb[k])
      return false;
  }
  // L = A_k x B_m.
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3;
    const int k2 = (k + 2) % 3;
    for (int m = 0; m < 3; ++m) {
      const int m1 = (m + 1) % 3;
      const int m2 = (m + 2) % 3;
      const double ra = ea[k1] * abs_r(k2, m) + ea[k2] * abs_r(k1, m);
      const double rb = eb[m1] * abs_r(k, m2) + eb[m2] * abs_r(k, m1);
      if (std::abs(t[k2] * r(k1, m) - t[k1] * r(k2, m)) > ra + rb)
        return false;
    }
  }
  return true;
}

}  // namespace partimix::dem
