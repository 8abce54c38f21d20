#pragma once
// The gauge of a superquadric grain (docs/dem.md, "Contact detection: what is implemented"):
// N(X) = (F(X) + 1)^(1/n1) = ((|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1)^(1/n1), the norm whose
// unit ball is the grain. G = N - 1 has the sign and the zero level set of F, but grows linearly
// away from the centre (N(s X) = s N(X)), so Newton's method sees a near-linear function even
// for blocky grains; F grows as |X|^n1.
#include "core/vec.hpp"
#include "dem/superquadric.hpp"

namespace partimix::dem {

// G = N - 1 at a body-frame point, with its gradient and Hessian.
struct GaugeLocal {
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();
};

// N(X) - 1 alone.
double gauge(const Superquadric& shape, const Vec3& x);
// N(X) - 1, its gradient and Hessian, from one computation of the powers. At the centre
// (N = 0) the derivatives are left zero.
GaugeLocal gauge_local(const Superquadric& shape, const Vec3& x);

}  // namespace partimix::dem
