#include "analysis/body_loads.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/body_load.hpp"

namespace partimix::analysis {
namespace {

const char* const kNames[] = {"force_x",       "force_y", "force_z",       "torque_own",
                              "torque_vessel", "power",   "power_rotation"};
const char* const kUnits[] = {"N", "N", "N", "N m", "N m", "W", "W"};

std::vector<Column> columns_of(const std::string& prefix) {
  std::vector<Column> columns;
  for (std::size_t k = 0; k < std::size(kNames); ++k)
    columns.push_back({prefix + kNames[k], kUnits[k]});
  return columns;
}

}  // namespace

BodyLoads::BodyLoads(const BodyOptions& body)
    : body_(body), history_(columns_of(fmt::format("body{}_", body.index))) {}

std::string BodyLoads::prefix() const {
  return fmt::format("body{}_", body_.index);
}

std::vector<Column> BodyLoads::columns() const {
  return columns_of(prefix());
}

void BodyLoads::sample(const ParticleStore& particles, double time, std::span<double> values) {
  const geometry::RigidPose pose = body_.motion->pose(time);
  const Vec3& axis = body_.motion_config.axis;
  const Vec3 own_axis_point = pose.place(body_.motion_config.axis_point);
  const BodyLoad load =
      measure_body_load(particles, body_.index, own_axis_point, body_.vessel_axis_point);
  values[0] = load.force.x();
  values[1] = load.force.y();
  values[2] = load.force.z();
  values[3] = axis.dot(load.torque_own);
  values[4] = axis.dot(load.torque_vessel);
  values[5] = power_given(load, pose, own_axis_point);
  values[6] = std::abs(pose.angular_velocity.dot(load.torque_own));
  history_.add(time, values);
}

void BodyLoads::replay(double time, std::span<const double> values) {
  history_.add(time, values);
}

void BodyLoads::add_figures(Figures& figures) const {
  history_.add_figures(figures, prefix(), revolution_period(body_.motion_config),
                       body_.average_revolutions);
}

void BodyLoads::add_caveats(Caveats& caveats) const {
  history_.add_caveats(caveats, revolution_period(body_.motion_config), body_.average_revolutions,
                       body_.motion_config.ramp_time);
}

}  // namespace partimix::analysis
