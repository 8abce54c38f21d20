#include "geometry/truck_drum_shape.hpp"

#include <stdexcept>

#include <Eigen/Geometry>

#include "geometry/mesh_shell_surface.hpp"
#include "geometry/truck_drum_mesh.hpp"

namespace partimix::geometry {

TruckDrumShape::TruckDrumShape(const TruckDrumParameters& parameters, const Vec3& axis_point,
                               const Vec3& axis, int divisions)
    : drum_(parameters), axis_point_(axis_point) {
  if (!(axis.norm() > 0.0))
    throw std::invalid_argument("the axis must not be the zero vector");
  rotation_ =
      Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis.normalized()).toRotationMatrix();
  triangles_ = truck_drum_surface_mesh(drum_, divisions);
  lower_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  upper_ = -lower_;
  for (Triangle& triangle : triangles_)
    for (Vec3& corner : triangle.corner) {
      corner = axis_point_ + rotation_ * corner;
      lower_ = lower_.cwiseMin(corner);
      upper_ = upper_.cwiseMax(corner);
    }
}

std::optional<bool> TruckDrumShape::blocks_grid_cell(const Vec3& x, double cell) const {
  const Vec3 local = to_drum(x);
  if (local.z() > drum_.length())
    return false;
  return drum_.shell_distance(local) > 0.0 || drum_.blade_distance(local) < 0.5 * cell;
}

double TruckDrumShape::signed_distance(const Vec3& x) const {
  return drum_.signed_distance(to_drum(x));
}

bool TruckDrumShape::beyond_open_end(const Vec3& x, const std::vector<Face>& /*open_faces*/) const {
  return to_drum(x).z() > drum_.length();
}

std::unique_ptr<Surface> TruckDrumShape::make_surface(bool /*solid*/,
                                                      const std::vector<Face>& /*open*/) const {
  return std::make_unique<MeshShellSurface>(triangles_);
}

}  // namespace partimix::geometry
