#include "analysis/power_number.hpp"

#include <cmath>

#include "analysis/body_load.hpp"

namespace partimix::analysis {
namespace {

// Distance of the body's own axis from the revolution axis: e''.
double revolution_radius(const geometry::MotionConfig& motion) {
  const Vec3 offset = motion.axis_point - motion.centre;
  return (offset - offset.dot(motion.axis) * motion.axis).norm();
}

}  // namespace

PowerScales power_scales(const geometry::MotionConfig& motion, double diameter) {
  if (!(diameter > 0.0))
    throw std::invalid_argument("the impeller diameter must be positive");
  const double spin = motion.rpm / 60.0;
  if (motion.type == "rotation" && spin != 0.0)
    return {std::abs(spin) * diameter, diameter};
  if (motion.type == "planetary") {
    const double d_g = 2.0 * revolution_radius(motion);
    const double u_ch = motion.revolution_rpm / 60.0 * d_g + spin * diameter;  // eq. 31
    if (!(u_ch > 0.0) || !(d_g > 0.0)) {
      throw std::invalid_argument(
          "eq. 31 needs u_ch = N_G d_G + N_R d_R > 0 and a revolution radius > 0");
    }
    return {u_ch, d_g};
  }
  throw std::invalid_argument("power numbers need a body in rotation or planetary motion");
}

double reynolds_number(const FlowScales& fluid, double metzner_otto, const PowerScales& scales) {
  const double n = fluid.flow_index;
  return fluid.density * std::pow(scales.velocity, 2.0 - n) * std::pow(scales.length, n) /
         (fluid.consistency * std::pow(metzner_otto, n - 1.0));
}

double power_number(double power, double density, const PowerScales& scales) {
  return power / (density * std::pow(scales.velocity, 3) * scales.length * scales.length);
}

PowerNumber::PowerNumber(const AnalysisOptions& options)
    : body_(options.body),
      density_(options.fluid.density),
      scales_(power_scales(options.body.motion_config, options.diameter)),
      reynolds_(reynolds_number(options.fluid, options.metzner_otto, scales_)),
      history_(columns()) {}

std::vector<Column> PowerNumber::columns() const {
  return {{"Re", ""}, {"Np", ""}, {"Np_total", ""}};
}

void PowerNumber::sample(const ParticleStore& particles, double time, std::span<double> values) {
  const geometry::RigidPose pose = body_.motion->pose(time);
  const Vec3 own_axis_point = pose.place(body_.motion_config.axis_point);
  const BodyLoad load =
      measure_body_load(particles, body_.index, own_axis_point, body_.vessel_axis_point);
  const double rotation_power = std::abs(pose.angular_velocity.dot(load.torque_own));
  values[0] = reynolds_;
  values[1] = power_number(rotation_power, density_, scales_);
  values[2] = power_number(power_given(load, pose, own_axis_point), density_, scales_);
  history_.add(time, values);
}

void PowerNumber::replay(double time, std::span<const double> values) {
  history_.add(time, values);
}

void PowerNumber::add_figures(Figures& figures) const {
  history_.add_figures(figures, "", revolution_period(body_.motion_config),
                       body_.average_revolutions);
}

void PowerNumber::add_caveats(Caveats& caveats) const {
  history_.add_caveats(caveats, revolution_period(body_.motion_config), body_.average_revolutions,
                       body_.motion_config.ramp_time);
}

}  // namespace partimix::analysis
