#include "geometry/truck_drum_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace partimix::geometry {
namespace {

Vec3 polar(double z, double theta, double rho) {
  return {rho * std::cos(theta), rho * std::sin(theta), z};
}

// The quad a b c d (counter-clockwise seen from outside) as two triangles.
void add_quad(TriangleSoup& out, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  out.push_back({{a, b, c}});
  out.push_back({{a, c, d}});
}

// A twisted quad as four triangles about its centre, which follows the ruled surface between
// its edges (two triangles cut a diagonal through it).
void add_twisted_quad(TriangleSoup& out, const Vec3& a, const Vec3& b, const Vec3& c,
                      const Vec3& d) {
  const Vec3 centre = 0.25 * (a + b + c + d);
  out.push_back({{a, b, centre}});
  out.push_back({{b, c, centre}});
  out.push_back({{c, d, centre}});
  out.push_back({{d, a, centre}});
}

// The blade's cross-section at z: inner and outer edge, each side of the sheet, the angular
// half-width at radius ρ being (t / 2) sqrt(1 + (ρ θ')²) / ρ (docs/truck-drum.md, "The blade's
// signed distance").
std::array<Vec3, 4> blade_section(const TruckDrumGeometry& drum, int segment, double turn, double z,
                                  double root_depth) {
  const TruckDrumParameters& p = drum.parameters();
  const double theta = drum.blade_angle(segment, z) + turn;
  const double outer = drum.radius_at(z) + root_depth;
  const double inner = drum.radius_at(z) - p.blade_height;
  const auto half_width = [&](double rho) {
    const double twist = rho * drum.blade_twist(segment, z);
    return 0.5 * p.blade_thickness * std::sqrt(1.0 + twist * twist) / rho;
  };
  return {polar(z, theta - half_width(inner), inner), polar(z, theta - half_width(outer), outer),
          polar(z, theta + half_width(outer), outer), polar(z, theta + half_width(inner), inner)};
}

void put_float(std::ostream& out, double value) {
  const auto f = static_cast<float>(value);
  out.write(reinterpret_cast<const char*>(&f), sizeof f);
}

}  // namespace

TriangleSoup truck_drum_shell_mesh(const TruckDrumGeometry& drum, int divisions, Opening opening) {
  divisions = std::max(divisions, 3);
  const TruckDrumParameters& p = drum.parameters();
  const std::array<double, 4> z{0.0, drum.segment_start(1), drum.segment_start(2), drum.length()};
  const std::array<double, 4> r{p.head_radius, p.radius, p.radius, p.opening_radius};
  std::vector<std::vector<Vec3>> rings(4);
  for (std::size_t k = 0; k < 4; ++k)
    for (int j = 0; j < divisions; ++j)
      rings[k].push_back(polar(z[k], 2.0 * std::numbers::pi * j / divisions, r[k]));
  TriangleSoup out;
  const Vec3 head(0.0, 0.0, 0.0);
  const Vec3 end(0.0, 0.0, drum.length());
  for (int j = 0; j < divisions; ++j) {
    const auto next = static_cast<std::size_t>((j + 1) % divisions);
    const auto here = static_cast<std::size_t>(j);
    out.push_back({{head, rings[0][next], rings[0][here]}});
    for (std::size_t k = 0; k < 3; ++k)
      add_quad(out, rings[k][here], rings[k][next], rings[k + 1][next], rings[k + 1][here]);
    if (opening == Opening::closed)
      out.push_back({{end, rings[3][here], rings[3][next]}});
  }
  return out;
}

TriangleSoup truck_drum_blade_mesh(const TruckDrumGeometry& drum, int segment, int blade,
                                   int divisions, double root_depth) {
  const double start = drum.segment_start(segment);
  const double end = drum.segment_start(segment + 1);
  const double turned = std::abs(drum.blade_angle(segment, end) - drum.blade_angle(segment, start));
  // A side of the strip twists by h_b Δθ across its height between stations: kept to half the
  // thickness, so that its faces stay within the blade (docs/truck-drum.md, "Meshes").
  const TruckDrumParameters& p = drum.parameters();
  const double step = std::min(2.0 * std::numbers::pi / std::max(divisions, 3),
                               0.5 * p.blade_thickness / p.blade_height);
  const double needed = std::ceil(turned / step) + 1.0;
  if (!(needed <= kMostBladeStations))
    throw std::invalid_argument(
        "the blades turn too far for their thickness against their height (a mesh of more than " +
        std::to_string(kMostBladeStations) +
        " stations per blade): thicken them or lower the "
        "helix angle");
  const int stations = std::max(2, static_cast<int>(needed));
  const double turn = blade * std::numbers::pi;
  std::vector<std::array<Vec3, 4>> sections;
  for (int i = 0; i < stations; ++i)
    sections.push_back(
        blade_section(drum, segment, turn, start + (end - start) * i / (stations - 1), root_depth));
  TriangleSoup out;
  for (std::size_t i = 0; i + 1 < sections.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t l = (k + 1) % 4;
      add_twisted_quad(out, sections[i][k], sections[i][l], sections[i + 1][l], sections[i + 1][k]);
    }
  const std::array<Vec3, 4>& first = sections.front();
  const std::array<Vec3, 4>& last = sections.back();
  add_quad(out, first[0], first[3], first[2], first[1]);
  add_quad(out, last[0], last[1], last[2], last[3]);
  return out;
}

TriangleSoup truck_drum_surface_mesh(const TruckDrumGeometry& drum, int divisions) {
  TriangleSoup out = truck_drum_shell_mesh(drum, divisions, Opening::open);
  const double root_depth = drum.parameters().blade_thickness;
  for (int segment = 0; segment < 3; ++segment)
    for (int blade = 0; blade < 2; ++blade) {
      const TriangleSoup strip = truck_drum_blade_mesh(drum, segment, blade, divisions, root_depth);
      out.insert(out.end(), strip.begin(), strip.end());
    }
  return out;
}

void write_stl(std::ostream& out, const TriangleSoup& triangles) {
  std::array<char, 80> header{};
  const std::string title = "partimix truck drum";
  std::copy(title.begin(), title.end(), header.begin());
  out.write(header.data(), header.size());
  const auto count = static_cast<std::uint32_t>(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  for (const Triangle& t : triangles) {
    const Vec3 normal = (t.corner[1] - t.corner[0]).cross(t.corner[2] - t.corner[0]).normalized();
    for (int a = 0; a < 3; ++a)
      put_float(out, normal[a]);
    for (const Vec3& c : t.corner)
      for (int a = 0; a < 3; ++a)
        put_float(out, c[a]);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), sizeof attribute);
  }
}

}  // namespace partimix::geometry
