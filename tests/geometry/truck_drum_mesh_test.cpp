// The truck drum's meshes (docs/truck-drum.md, "Meshes and the STL export"): the shell's and
// each blade's triangles make closed, consistently wound meshes (geometry::TriangleMesh refuses
// any other); the shell mesh's signed distance matches the analytic shell's within the chords'
// sagitta R (1 - cos(π / n)); each blade mesh encloses the blade's volume, ∫ dz ∫ t sqrt(1 +
// (ρ θ')²) dρ over its strip, within 0.5% (set before the first run, which gave 8% with stations
// every 2π/96 and two triangles per twisted side; docs/truck-drum.md, "Meshes"); an STL written
// and read back gives the same triangles to float precision.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "eight_cubic_metre_drum.hpp"
#include "geometry/triangle_mesh.hpp"
#include "geometry/truck_drum_mesh.hpp"
#include "support/case_run.hpp"

namespace partimix::geometry {
namespace {

constexpr int kDivisions = 96;

TruckDrumGeometry drum() {
  return TruckDrumGeometry(eight_cubic_metre_drum());
}

// The volume a closed, outward-wound soup encloses (the divergence theorem).
double enclosed_volume(const TriangleSoup& soup) {
  double volume = 0.0;
  for (const Triangle& t : soup)
    volume += t.corner[0].dot(t.corner[1].cross(t.corner[2])) / 6.0;
  return std::abs(volume);
}

TEST(TruckDrumMesh, TheShellIsClosedAndMatchesTheAnalyticShell) {
  const TruckDrumGeometry geometry = drum();
  const TriangleMesh mesh(truck_drum_shell_mesh(geometry, kDivisions));
  const double sagitta = 1.15 * (1.0 - std::cos(std::numbers::pi / kDivisions));
  double largest = 0.0;
  for (const double z : {-0.1, 0.4, 1.7, 2.5, 3.3, 4.0, 5.2, 5.5})
    for (const double rho : {0.1, 0.5, 0.8, 1.1, 1.3})
      for (const double theta : {0.0, 0.7, 2.9}) {
        const Vec3 x(rho * std::cos(theta), rho * std::sin(theta), z);
        largest = std::max(largest, std::abs(mesh.signed_distance(x) - geometry.shell_distance(x)));
      }
  std::printf("shell mesh: %zu triangles, largest difference %.2e m, sagitta %.2e m\n",
              mesh.triangle_count(), largest, sagitta);
  EXPECT_LE(largest, sagitta + 1e-12);
}

TEST(TruckDrumMesh, EachBladeIsClosedAndEnclosesTheBladesVolume) {
  const TruckDrumGeometry geometry = drum();
  for (int s = 0; s < 3; ++s)
    for (int b = 0; b < 2; ++b) {
      const TriangleSoup soup = truck_drum_blade_mesh(geometry, s, b, kDivisions);
      ASSERT_NO_THROW(TriangleMesh{soup}) << s << " " << b;
      // ∫ dz ∫ t sqrt(1 + (ρ θ')²) dρ by the midpoint rule, 2000 x 50.
      const double z0 = geometry.segment_start(s);
      const double z1 = geometry.segment_start(s + 1);
      double volume = 0.0;
      const int nz = 2000;
      const int nr = 50;
      for (int i = 0; i < nz; ++i) {
        const double z = z0 + (i + 0.5) * (z1 - z0) / nz;
        const double r = geometry.radius_at(z);
        for (int k = 0; k < nr; ++k) {
          const double rho = r - 0.25 + (k + 0.5) * 0.25 / nr;
          const double twist = rho * geometry.blade_twist(s, z);
          volume += 0.008 * std::sqrt(1.0 + twist * twist) * (0.25 / nr) * ((z1 - z0) / nz);
        }
      }
      EXPECT_NEAR(enclosed_volume(soup), volume, 5e-3 * volume) << s << " " << b;
    }
}

TEST(TruckDrumMesh, AnStlWrittenReadsBackTheSameTriangles) {
  const test_support::TempDir dir;
  const TriangleSoup soup = truck_drum_blade_mesh(drum(), 1, 0, kDivisions);
  const std::string path = (dir / "blade.stl").string();
  {
    std::ofstream out(path, std::ios::binary);
    write_stl(out, soup);
    ASSERT_TRUE(out.good());
  }
  const TriangleSoup back = read_stl(path);
  ASSERT_EQ(back.size(), soup.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < soup.size(); ++i)
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, (back[i].corner[c] - soup[i].corner[c]).norm());
  EXPECT_LT(largest, 1e-6);
}

}  // namespace
}  // namespace partimix::geometry
