// The fluid's clearance from solid bodies (sph/body_clearance.hpp, docs/geometry-meshes.md,
// "Solid walls"): on the fluid's own lattice the fluid and a curved body tile the lattice (no
// point left empty between them, the defect that made a turning cylinder's torque 9% low); on a
// lattice of another phase no fluid point comes closer than a spacing to a body particle; the
// test sees across a periodic boundary.
#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/lattice.hpp"
#include "geometry/shape.hpp"
#include "sph/body_clearance.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 0.01;

Domain box_domain() {
  Domain d;
  d.lo = Vec3(-0.2, -0.2, 0.0);
  d.hi = Vec3(0.2, 0.2, 0.1);
  return d;
}

double nearest(const Vec3& x, const std::vector<Vec3>& points) {
  double best = 1e300;
  for (const Vec3& p : points)
    best = std::min(best, (x - p).norm());
  return best;
}

TEST(BodyClearance, OnOneLatticeTheFluidAndACurvedBodyTileIt) {
  const Domain domain = box_domain();
  // Base corners 0.1 m apart: a whole number of spacings, so one lattice phase.
  const geometry::Cylinder region(Vec3(0.0, 0.0, 0.0), 0.15, 0.1);
  const geometry::Cylinder body(Vec3(0.0, 0.0, 0.0), 0.05, 0.1);
  const std::vector<Vec3> particles = geometry::inside_layers(body, kSpacing, 3, domain);
  BodyClearance clearance(domain, kSpacing);
  clearance.add_body(body, particles);
  const std::vector<Vec3> lattice = geometry::fill(region, kSpacing, domain);
  int kept = 0;
  int outside = 0;
  for (const Vec3& x : lattice) {
    const bool blocked = clearance.blocks(x);
    outside += body.signed_distance(x) >= 0.0 ? 1 : 0;
    kept += blocked ? 0 : 1;
    if (!blocked) {
      EXPECT_GE(nearest(x, particles), kSpacing * (1.0 - 1e-9));
    }
  }
  EXPECT_EQ(kept, outside);  // every point outside the body is fluid: nothing left empty
  EXPECT_GT(std::count_if(lattice.begin(), lattice.end(),
                          [&](const Vec3& x) {
                            const double d = body.signed_distance(x);
                            return d >= 0.0 && d < 0.5 * kSpacing;
                          }),
            0);  // points a half spacing clearance would have dropped
}

TEST(BodyClearance, OnAnotherPhaseNoFluidPointComesWithinASpacing) {
  const Domain domain = box_domain();
  const geometry::Cylinder region(Vec3(0.0, 0.0, 0.0), 0.15, 0.1);
  const geometry::Cylinder body(Vec3(0.0031, -0.0047, 0.0), 0.05, 0.1);
  const std::vector<Vec3> particles = geometry::inside_layers(body, kSpacing, 3, domain);
  BodyClearance clearance(domain, kSpacing);
  clearance.add_body(body, particles);
  int kept = 0;
  for (const Vec3& x : geometry::fill(region, kSpacing, domain)) {
    if (clearance.blocks(x))
      continue;
    ++kept;
    EXPECT_GE(body.signed_distance(x), 0.0);
    EXPECT_GE(nearest(x, particles), kSpacing * (1.0 - 1e-9));
  }
  EXPECT_GT(kept, 0);
}

TEST(BodyClearance, SeesAcrossAPeriodicBoundary) {
  Domain domain = box_domain();
  domain.periodic[2] = true;
  const geometry::Box body(Vec3(-0.05, -0.05, 0.09), Vec3(0.05, 0.05, 0.1));
  const std::vector<Vec3> particle{Vec3(0.0, 0.0, 0.0995)};
  BodyClearance clearance(domain, kSpacing);
  clearance.add_body(body, particle);
  EXPECT_TRUE(clearance.blocks(Vec3(0.0, 0.0, 0.004)));   // 0.0045 m away through the boundary
  EXPECT_FALSE(clearance.blocks(Vec3(0.0, 0.0, 0.012)));  // 0.0125 m away
}

}  // namespace
}  // namespace partimix::sph
