#include "geometry/shape.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/box_container_surface.hpp"
#include "geometry/cylinder_vessel_surface.hpp"
#include "geometry/solid_box_surface.hpp"
#include "geometry/solid_cylinder_surface.hpp"

namespace partimix::geometry {

bool Shape::beyond_open_end(const Vec3& x, const std::vector<Face>& open_faces) const {
  for (const Face& face : open_faces) {
    if (face.side > 0 && x[face.axis] > upper()[face.axis])
      return true;
    if (face.side < 0 && x[face.axis] < lower()[face.axis])
      return true;
  }
  return false;
}

double Box::signed_distance(const Vec3& x) const {
  const Vec3 centre = 0.5 * (lo_ + hi_);
  const Vec3 half = 0.5 * (hi_ - lo_);
  const Vec3 d = (x - centre).cwiseAbs() - half;
  const double outside = d.cwiseMax(0.0).norm();
  const double inside = std::min(d.maxCoeff(), 0.0);
  return outside + inside;
}

std::unique_ptr<Surface> Box::make_surface(bool solid, const std::vector<Face>& open_faces) const {
  if (solid)
    return std::make_unique<SolidBoxSurface>(lo_, hi_);
  return std::make_unique<BoxContainerSurface>(lo_, hi_, open_faces);
}

double Cylinder::signed_distance(const Vec3& x) const {
  const double radial = std::hypot(x.x() - base_.x(), x.y() - base_.y()) - radius_;
  const double axial = std::abs(x.z() - (base_.z() + 0.5 * height_)) - 0.5 * height_;
  const double outside = std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
  const double inside = std::min(std::max(radial, axial), 0.0);
  return outside + inside;
}

std::unique_ptr<Surface> Cylinder::make_surface(bool solid,
                                                const std::vector<Face>& open_faces) const {
  if (solid)
    return std::make_unique<SolidCylinderSurface>(base_, radius_, height_);
  return std::make_unique<CylinderVesselSurface>(base_, radius_, height_, open_faces);
}

}  // namespace partimix::geometry
