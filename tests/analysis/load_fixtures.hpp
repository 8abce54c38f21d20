#pragma once
// Hand-built inputs for the analysis tests (docs/power.md, docs/mixing.md): particle stores with
// the fields the SPH solver and MovingBodies add for body loads ("body", "body_force",
// "body_couple"), bodies with a prescribed motion as the runner hands them to the analyses, and
// a rotor whose loads are worked out by hand.
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include "analysis/analysis.hpp"
#include "geometry/motion.hpp"
#include "particles/particle_store.hpp"

namespace partimix::analysis_test {

constexpr double kPi = std::numbers::pi;

// Appends one particle of `kind` at `x` with `tag`; its index.
inline std::size_t add_particle(ParticleStore& store, ParticleKind kind, const Vec3& x,
                                std::int32_t tag = 0) {
  const std::size_t i = store.size();
  store.resize(i + 1);
  store.kind()[i] = static_cast<std::int32_t>(kind);
  store.position()[i] = x;
  store.tag()[i] = tag;
  store.id()[i] = static_cast<std::int64_t>(i);
  return i;
}

// What the solver leaves on one particle for the load analyses.
struct Load {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 force = Vec3::Zero();   // "body_force" [N]
  Vec3 couple = Vec3::Zero();  // "body_couple" [N m]
};

// A store with the fields "body", "body_force" and "body_couple".
class LoadedStore {
 public:
  LoadedStore()
      : body_(store_.add_integer("body", "")),
        force_(store_.add_vector("body_force", "N", false)),
        couple_(store_.add_vector("body_couple", "N m", false)) {}

  // A wall particle of `body`, or a fluid particle (body -1) when `body` < 0.
  void add(int body, const Load& load) {
    const std::size_t i =
        add_particle(store_, body < 0 ? ParticleKind::fluid : ParticleKind::wall, load.position);
    store_.velocity()[i] = load.velocity;
    body_.values[i] = body;
    force_.values[i] = load.force;
    couple_.values[i] = load.couple;
  }

  const ParticleStore& store() const { return store_; }

 private:
  ParticleStore store_;
  Field<std::int32_t>& body_;
  Field<Vec3>& force_;
  Field<Vec3>& couple_;
};

inline geometry::MotionConfig rotation(const Vec3& axis_point, double rpm, double ramp_time = 0.0) {
  geometry::MotionConfig motion;
  motion.type = "rotation";
  motion.axis_point = axis_point;
  motion.rpm = rpm;
  motion.ramp_time = ramp_time;
  return motion;
}

inline geometry::MotionConfig planetary(const Vec3& own_axis_point, const Vec3& centre, double rpm,
                                        double revolution_rpm) {
  geometry::MotionConfig motion;
  motion.type = "planetary";
  motion.axis_point = own_axis_point;
  motion.centre = centre;
  motion.rpm = rpm;
  motion.revolution_rpm = revolution_rpm;
  return motion;
}

// A body with its motion, as the runner builds BodyOptions from the case.
struct MovingBody {
  MovingBody(int index, const geometry::MotionConfig& config, const Vec3& vessel_axis_point,
             double average_revolutions = 1.0)
      : motion(geometry::motion_registry().create(config.type, config)),
        options{index, motion.get(), config, vessel_axis_point, average_revolutions} {}

  std::unique_ptr<geometry::Motion> motion;
  analysis::BodyOptions options;
};

// The rotor of the load tests: body 0 turns about z through kRotorAxis at 120 rpm
// (N = 2 r/s, omega = 4 pi rad/s). Its two particles, 0.05 m either side of the axis along x,
// carry the rigid velocities omega x r = (0, +-0.2 pi, 0) and, times `scale`, the forces
// (0, -1, 0) at x = 0.55 and (0, 2, 0) at x = 0.45 and the couples (0, 0, -0.01) each. A fluid
// particle and a particle of body 1 carry loads that must not count. For scale 1, about the
// axis point and the vessel axis point kRotorVessel = (0.3, 0.5, 0):
//   F = (0, 1, 0) N
//   Gamma_own,z    = 0.05 (-1) + (-0.05)(2) - 0.02 = -0.17 N m
//   Gamma_vessel,z = 0.25 (-1) + 0.15 (2) - 0.02   = +0.03 N m
//                    (= Gamma_own + ((0.5, 0.5) - (0.3, 0.5)) x F = -0.17 + 0.2)
//   power          = -sum f.u = -((-1)(0.2 pi) + (2)(-0.2 pi)) = 0.6 pi W
//   power_rotation = |omega Gamma_own| = 4 pi 0.17 = 0.68 pi W
// All of them scale with `scale`.
inline const Vec3 kRotorAxis(0.5, 0.5, 0.0);
inline const Vec3 kRotorVessel(0.3, 0.5, 0.0);
constexpr double kRotorRpm = 120.0;

inline void add_rotor(LoadedStore& store, double scale) {
  const double tip = 0.2 * kPi;  // omega r = 4 pi 0.05
  const Vec3 couple(0.0, 0.0, -0.01 * scale);
  store.add(-1, {Vec3(0.5, 0.6, 0.0), Vec3::Zero(), Vec3(5.0, 5.0, 0.0), Vec3(0.0, 0.0, 3.0)});
  store.add(0, {Vec3(0.55, 0.5, 0.0), Vec3(0.0, tip, 0.0), Vec3(0.0, -scale, 0.0), couple});
  store.add(1, {Vec3(0.5, 0.4, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0, 7.0, 0.0), Vec3(0, 0, 1.0)});
  store.add(0, {Vec3(0.45, 0.5, 0.0), Vec3(0.0, -tip, 0.0), Vec3(0.0, 2.0 * scale, 0.0), couple});
}

// A store holding the rotor alone.
class RotorStore : public LoadedStore {
 public:
  explicit RotorStore(double scale) { add_rotor(*this, scale); }
};

// The values of one sample of `analysis`.
inline std::vector<double> sample_once(analysis::Analysis& analysis, const ParticleStore& particles,
                                       double time) {
  std::vector<double> values(analysis.columns().size());
  analysis.sample(particles, time, values);
  return values;
}

// Samples `analysis` from `first` at t = 0, 0.25, 0.5 s and from `second` at t = 0.75, 1 s.
// With a value A from `first` and B from `second`, the trapezoidal mean over the rotor's last
// revolution [0.5, 1] (period 60/120 = 0.5 s) is
//   ((A + B)/2 0.25 + B 0.25) / 0.5 = (A + 3 B) / 4,
// and over two revolutions [0, 1]: A 0.5 + (A + B)/2 0.25 + B 0.25 = (5 A + 3 B) / 8.
inline void sample_step_history(analysis::Analysis& analysis, const ParticleStore& first,
                                const ParticleStore& second) {
  for (const double t : {0.0, 0.25, 0.5})
    sample_once(analysis, first, t);
  for (const double t : {0.75, 1.0})
    sample_once(analysis, second, t);
}

}  // namespace partimix::analysis_test
