#include "geometry/cylinder_vessel_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/contact_selection.hpp"

#include "geometry/meridian.hpp"

namespace partimix::geometry {
namespace {

// A point of one of the vessel's segments in the meridian plane, with that segment's inward
// normal (n_r, n_z) and whether the centre projects inside the segment.
struct Candidate {
  double r = 0.0;
  double z = 0.0;
  double n_r = 0.0;
  double n_z = 0.0;
  bool within = false;
};

// The nearest point to (r, z) over the side and the closed discs (side, bottom, top on a tie).
Candidate nearest_part(double r, double z, double radius, double height, bool bottom_closed,
                       bool top_closed) {
  const double r_disc = std::min(r, radius);
  Candidate parts[3];
  int count = 0;
  parts[count++] = {radius, std::clamp(z, 0.0, height), -1.0, 0.0, z >= 0.0 && z <= height};
  if (bottom_closed)
    parts[count++] = {r_disc, 0.0, 0.0, 1.0, r <= radius};
  if (top_closed)
    parts[count++] = {r_disc, height, 0.0, -1.0, r <= radius};
  int best = 0;
  double best_squared = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k) {
    const double dr = r - parts[k].r;
    const double dz = z - parts[k].z;
    const double squared = dr * dr + dz * dz;
    if (squared < best_squared) {
      best_squared = squared;
      best = k;
    }
  }
  return parts[best];
}

}  // namespace

CylinderVesselSurface::CylinderVesselSurface(const Vec3& base_centre, double radius, double height,
                                             const std::vector<Face>& open_faces)
    : base_(base_centre), radius_(radius), height_(height) {
  for (const Face& face : open_faces) {
    if (face.axis == 2 && face.side < 0)
      bottom_closed_ = false;
    if (face.axis == 2 && face.side > 0)
      top_closed_ = false;
  }
}

// Outside the cylinder, and not through an open disc.
bool CylinderVesselSurface::crossed(double r, double z) const {
  if ((z < 0.0 && !bottom_closed_) || (z > height_ && !top_closed_))
    return false;
  return r > radius_ || z < 0.0 || z > height_;
}

bool CylinderVesselSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const Meridian m = meridian(centre, base_, Vec3::UnitZ());
  const Candidate p = nearest_part(m.r, m.z, radius_, height_, bottom_closed_, top_closed_);
  const double dr = m.r - p.r;
  const double dz = m.z - p.z;
  double n_r = p.n_r;
  double n_z = p.n_z;
  double gap = dr * n_r + dz * n_z;
  const double distance = std::hypot(dr, dz);
  if (!p.within && distance > 0.0) {
    // A rim: on the rim itself (distance 0) the segment's normal stands in, with gap 0.
    const double sign = crossed(m.r, m.z) ? -1.0 : 1.0;
    n_r = sign * dr / distance;
    n_z = sign * dz / distance;
    gap = sign * distance;
  }
  if (gap > reach)
    return false;
  const Vec3 e_z = Vec3::UnitZ();
  out = {base_ + p.r * m.e_r + p.z * e_z, n_r * m.e_r + n_z * e_z, gap};
  return true;
}

// The side: the infinite cylinder, or its rim circle beyond an open disc.
SurfacePoint CylinderVesselSurface::on_side(const Vec3& point) const {
  const Meridian m = meridian(point, base_, Vec3::UnitZ());
  const Vec3 e_z = Vec3::UnitZ();
  const bool rim = (m.z < 0.0 && !bottom_closed_) || (m.z > height_ && !top_closed_);
  if (!rim)
    return {base_ + radius_ * m.e_r + m.z * e_z, -m.e_r, radius_ - m.r, 0};
  const double z = std::clamp(m.z, 0.0, height_);
  const double dr = m.r - radius_;
  const double dz = m.z - z;
  const double distance = std::hypot(dr, dz);
  const Vec3 normal = distance > 0.0 ? Vec3((dr * m.e_r + dz * e_z) / distance) : Vec3(-m.e_r);
  return {base_ + radius_ * m.e_r + z * e_z, normal, distance, 0};
}

bool CylinderVesselSurface::nearest_on_face(int face, const Vec3& point, double reach,
                                            SurfacePoint& out) const {
  const Vec3 e_z = Vec3::UnitZ();
  const double z = (point - base_).dot(e_z);
  if (face == 0) {
    out = on_side(point);
  } else if (face == 1 && bottom_closed_) {
    out = {point - z * e_z, e_z, z, 1};
  } else if (face == 2 && top_closed_) {
    out = {point + (height_ - z) * e_z, -e_z, height_ - z, 2};
  } else {
    return false;
  }
  return out.gap <= reach;
}

int CylinderVesselSurface::face_points(const Vec3& centre, double reach,
                                       std::span<SurfacePoint, 3> out) const {
  int count = 0;
  for (int face = 0; face < 3; ++face) {
    if (nearest_on_face(face, centre, reach, out[count]))
      ++count;
  }
  sort_deepest_first(out.first(count));
  return count;
}

// Every face point is a contact: the rim circles of open discs touch no other face.
int CylinderVesselSurface::contacts(const Vec3& centre, double reach,
                                    std::span<SurfacePoint> out) const {
  std::array<SurfacePoint, 3> candidates;
  const int count = std::min(face_points(centre, reach, candidates), static_cast<int>(out.size()));
  std::copy_n(candidates.begin(), count, out.begin());
  return count;
}

int CylinderVesselSurface::faces_near(const Vec3& centre, double reach, std::span<int> out) const {
  std::array<SurfacePoint, 3> candidates;
  const int count = std::min(face_points(centre, reach, candidates), static_cast<int>(out.size()));
  for (int k = 0; k < count; ++k)
    out[k] = candidates[k].face;
  return count;
}

}  // namespace partimix::geometry
