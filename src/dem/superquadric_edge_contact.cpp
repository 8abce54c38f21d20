#include "dem/superquadric_edge_contact.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace partimix::dem {
namespace {

constexpr int kBisections = 64;  // an arc's angle to 2^-64 of it
constexpr int kArcSamples = 8;
constexpr int kCornerIterations = 40;
constexpr double kSettled = 1e-12;        // rad: a corner's iteration has settled below this move
constexpr double kLongestReach = 1024.0;  // steps

// The grain, and its deepest point against a unit normal m out of the wall: its support point in
// the direction -m.
struct Grain {
  const Superquadric& shape;
  const Vec3& centre;
  const Mat3& rotation;

  Vec3 deepest(const Vec3& m) const {
    return centre + rotation * shape.support(rotation.transpose() * (-m));
  }
};

// A unit normal m, the grain's deepest point X against it, and the overlap f = m . (p - X) of the
// grain with the half-space behind the plane through p normal to m.
struct Along {
  Vec3 normal;
  Vec3 deepest;
  double overlap;
};

Along along(const Grain& grain, const Vec3& p, const Vec3& m) {
  const Vec3 deepest = grain.deepest(m);
  return {m, deepest, m.dot(p - deepest)};
}

// The least f on the great-circle arc m(theta) = cos theta a + sin theta v from the unit normal a
// to the unit normal b (a != b, less than pi apart). X is extremal along m, so m . dX = 0 and
// f' = m' . (p - X(m)). f is convex while it is below the grain's radius of curvature in the
// arc's plane (f + f'' is that radius), but need not be for deep overlaps or sharp grains: the
// lowest of kArcSamples + 1 angles first, then, unless that is an end where f' says so, the
// root of f' between its neighbours by bisection on the sign of f' (which, unlike f near its
// least, round-off does not hide). `nearer_b`: the least lies in the half of the arc next to b.
struct ArcLeast {
  Along at;
  bool nearer_b;
};

ArcLeast arc_least(const Grain& grain, const Vec3& p, const Vec3& unit_a, const Vec3& unit_b) {
  // Unit to round-off, and v normal to a: for a short arc b - (b . a) a is all cancellation, so
  // a direction a hair off unit would turn v well off normal (and the arc's sign with it).
  const Vec3 a = unit_a.normalized();
  const Vec3 b = unit_b.normalized();
  Vec3 v = (b - b.dot(a) * a).normalized();
  v = (v - v.dot(a) * a).normalized();
  const double arc = std::atan2(b.dot(v), b.dot(a));
  const auto normal_at = [&](double angle) {
    return Vec3((std::cos(angle) * a + std::sin(angle) * v).normalized());
  };
  const auto slope_at = [&](double angle) {
    const Vec3 turning = -std::sin(angle) * a + std::cos(angle) * v;
    return turning.dot(p - grain.deepest(normal_at(angle)));
  };
  const auto sample = [&](int k) { return arc * k / kArcSamples; };
  int lowest = 0;
  Along best = along(grain, p, a);
  for (int k = 1; k <= kArcSamples; ++k) {
    const Along here = along(grain, p, normal_at(sample(k)));
    if (here.overlap < best.overlap) {
      best = here;
      lowest = k;
    }
  }
  const bool at_end =
      (lowest == 0 && slope_at(0.0) >= 0.0) || (lowest == kArcSamples && slope_at(arc) <= 0.0);
  double angle = sample(lowest);
  if (!at_end) {
    double low = sample(std::max(lowest - 1, 0));
    double high = sample(std::min(lowest + 1, kArcSamples));
    for (int step = 0; step < kBisections && low < high; ++step) {
      const double middle = 0.5 * (low + high);
      (slope_at(middle) < 0.0 ? low : high) = middle;
    }
    const Along root = along(grain, p, normal_at(0.5 * (low + high)));
    if (root.overlap <= best.overlap) {
      best = root;
      angle = 0.5 * (low + high);
    }
  }
  return {best, angle > 0.5 * arc};
}

// The unit direction of the sum of the corner's normals, inside its cone.
Vec3 cone_middle(const geometry::Ridge& ridge) {
  Vec3 middle = Vec3::Zero();
  for (int k = 0; k < ridge.count; ++k)
    middle += ridge.normals[k];
  return middle.normalized();
}

// Whether the unit normal m lies in the corner's cone of normals, a convex spherical polygon: on
// the inner side of each of its arcs, as its middle is.
bool in_cone(const geometry::Ridge& ridge, const Vec3& middle, const Vec3& m) {
  for (int k = 0; k < ridge.count; ++k) {
    const Vec3 side = ridge.normals[k].cross(ridge.normals[(k + 1) % ridge.count]);
    if (side.dot(m) * side.dot(middle) < 0.0)
      return false;
  }
  return true;
}

// The least f over the corner's cone of normals, from its middle, while f is convex there: quasi-
// Newton (BFGS; Nocedal & Wright 2006, "Numerical Optimization", section 6.1) in the
// gnomonic chart m = w / |w|, w = middle + xi_1 e1 + xi_2 e2, whose straight lines are great
// circles, each step's line searched exactly by arc_least (over twice the step, and four times
// as far again after a search that ended at the end of its line: far from the least, f can be
// nearly straight, and BFGS's curvature then says nothing). The gradient is exact:
// dF/dxi = E^T (p - X - f m) / |w|, E = (e1 e2) (f's gradient on the sphere is the part of
// p - X across m). kLeft when it leaves the cone (the least is then on the cone's boundary),
// kStuck when it does not settle.
enum class Search { kFound, kLeft, kStuck };

Search least_inside(const Grain& grain, const geometry::Ridge& ridge, const Vec3& middle,
                    Along& out) {
  const Vec3& p = ridge.start;
  const Vec3 e1 = middle.unitOrthogonal();
  const Vec3 e2 = middle.cross(e1);
  // Explicit return types: an Eigen expression returned through `auto` would outlive its terms.
  const auto chart = [&](const Vec3& normal) -> Eigen::Vector2d {
    const Vec3 w = normal / normal.dot(middle);
    return {e1.dot(w), e2.dot(w)};
  };
  const auto normal_at = [&](const Eigen::Vector2d& xi) -> Vec3 {
    return (middle + xi.x() * e1 + xi.y() * e2).normalized();
  };
  const auto gradient_at = [&](const Along& here) -> Eigen::Vector2d {
    const Vec3 across = p - here.deepest - here.overlap * here.normal;
    const double shrink = here.normal.dot(middle);  // 1 / |w|
    return {shrink * e1.dot(across), shrink * e2.dot(across)};
  };
  Eigen::Vector2d xi = Eigen::Vector2d::Zero();
  Along here = along(grain, p, middle);
  Eigen::Vector2d gradient = gradient_at(here);
  Eigen::Matrix2d inverse = Eigen::Matrix2d::Identity() / grain.shape.bounding_radius();
  double reach = 2.0;  // the line searched, in steps; longer while each search ends at its end
  for (int k = 0; k < kCornerIterations; ++k) {
    const Eigen::Vector2d step = -inverse * gradient;
    const Vec3 ahead = normal_at(xi + reach * step);
    if (!(step.norm() > kSettled) || !((ahead - here.normal).norm() > 0.0)) {
      out = here;
      return Search::kFound;
    }
    const Along next = arc_least(grain, p, here.normal, ahead).at;
    if (!in_cone(ridge, middle, next.normal))
      return Search::kLeft;
    const Eigen::Vector2d moved = chart(next.normal) - xi;
    const Eigen::Vector2d next_gradient = gradient_at(next);
    const Eigen::Vector2d change = next_gradient - gradient;
    reach = moved.norm() >= 0.99 * reach * step.norm() ? std::min(4.0 * reach, kLongestReach) : 2.0;
    xi += moved;
    here = next;
    gradient = next_gradient;
    if (moved.norm() <= kSettled) {
      out = here;
      return Search::kFound;
    }
    if (const double curving = moved.dot(change); curving > 0.0) {
      const Eigen::Matrix2d keep =
          Eigen::Matrix2d::Identity() - moved * change.transpose() / curving;
      inverse = keep * inverse * keep.transpose() + moved * moved.transpose() / curving;
    }
  }
  out = here;
  return Search::kStuck;
}

WallContact contact_of(const Along& least, int face, bool converged) {
  return {least.overlap > 0.0,
          converged,
          least.normal,
          least.overlap,
          least.deepest + 0.5 * least.overlap * least.normal,
          geometry::SurfacePoint{least.deepest + least.overlap * least.normal, least.normal,
                                 -least.overlap, face}};
}

// A corner of three or more faces: the least f over its cone of normals. First the least over the
// cone's boundary, its arcs (each the cone of one of the corner's edges). Where that is not
// positive the grain is apart from the corner's solid, and no more is needed; else, the grain
// overlapping every edge's wedge, f is convex over the cone (docs/dem.md) and its least lies
// inside it where the search from the cone's middle settles there, else on the boundary.
WallContact corner_contact(const Grain& grain, const geometry::Ridge& ridge) {
  Along least{ridge.normals[0], ridge.start, std::numeric_limits<double>::infinity()};
  int face = ridge.faces[0];
  for (int k = 0; k < ridge.count; ++k) {
    const int next = (k + 1) % ridge.count;
    const ArcLeast arc = arc_least(grain, ridge.start, ridge.normals[k], ridge.normals[next]);
    if (arc.at.overlap < least.overlap) {
      least = arc.at;
      face = ridge.faces[arc.nearer_b ? next : k];
    }
  }
  if (!(least.overlap > 0.0))
    return contact_of(least, face, true);
  Along inside = least;
  const Search search = least_inside(grain, ridge, cone_middle(ridge), inside);
  if (search != Search::kFound || !(inside.overlap < least.overlap))
    return contact_of(least, face, search != Search::kStuck);
  int nearest = 0;
  for (int k = 1; k < ridge.count; ++k)
    nearest = inside.normal.dot(ridge.normals[k]) > inside.normal.dot(ridge.normals[nearest])
                  ? k
                  : nearest;
  return contact_of(inside, ridge.faces[nearest], true);
}

}  // namespace

WallContact edge_contact(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                         const geometry::Ridge& ridge) {
  const Grain grain{shape, centre, rotation};
  if (ridge.count > 2)
    return corner_contact(grain, ridge);
  const ArcLeast least = arc_least(grain, ridge.start, ridge.normals[0], ridge.normals[1]);
  return contact_of(least.at, ridge.faces[least.nearer_b ? 1 : 0], true);
}

}  // namespace partimix::dem
