#pragma once
// The droplet measurements of the multi-material SPH scheme (docs/multi-material-sph.md, "The
// scheme"; docs/case-reference.md, "analyses", droplet): every sample, over all the method's
// particles (the droplet), the diameter D of the shell's outline (outline_diameter, from the
// mean distances of its surfaces' particles from the droplet's centroid and its volume sum
// m / rho) and its ratio to the first sample's D0; the volume-weighted median pressure above the
// ambient of the particles inside the shell (all that are not shell: liquid and gas), which the
// layers along the interfaces between materials, whose pressures stray far from the bulk's, do
// not move as they move the mean; the largest damage of the shell; the
// mass-weighted mean temperature of the gas; and whether the shell has ruptured: a path of fully
// damaged particles through it (ShellRupture) or, in 2D, its intact particles no longer closing
// round the centroid (ShellRing).
// The shell's inner and outer surfaces are labelled at the first sample by each shell particle's
// distance from the droplet's centroid, and kept by particle id. The summary: the largest D / D0,
// the time of the first sample that finds the shell ruptured, the pressure then, and the pressure
// at the sample nearest a set time after it (0.1 s by default).
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "analysis/analysis.hpp"
#include "analysis/droplet_fields.hpp"
#include "analysis/droplet_measures.hpp"
#include "analysis/droplet_options.hpp"
#include "analysis/shell_ring.hpp"
#include "analysis/shell_rupture.hpp"

namespace partimix::analysis {

class Droplet final : public Analysis {
 public:
  // Throws std::invalid_argument without a shell material, with link <= 0, after_rupture <= 0
  // or with dimensions other than 2 and 3.
  explicit Droplet(const DropletOptions& options);
  std::vector<Column> columns() const override;
  // Throws RunError when the particles lack a field of the multi-material scheme (material,
  // density, pressure, temperature, damage).
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  // The surfaces cannot be replayed: a resumed run labels them at its first sample.
  void replay(double time, std::span<const double> values) override;
  // diameter_ratio_max [-]; once ruptured rupture_time [s] and pressure_at_rupture [Pa]; once a
  // sample at or past rupture_time + after_rupture has come, pressure_after_rupture [Pa].
  void add_figures(Figures& figures) const override;
  // rupture_time when the shell has not ruptured or its surfaces were labelled on resuming;
  // pressure_after_rupture when the run ended too soon after the rupture.
  void add_caveats(Caveats& caveats) const override;

 private:
  struct Rupture {
    double time;      // [s]
    double pressure;  // pressure_above_ambient then [Pa]
  };
  bool is_shell(const ParticleStore& particles, const DropletFields& fields, std::size_t i) const;
  void label_surfaces(const ParticleStore& particles, const DropletFields& fields,
                      const Vec3& centre, double time);
  // Gathers the shell's particles (positions, damage, surfaces and volume) for the measures below.
  void collect_shell(const ParticleStore& particles, const DropletFields& fields);
  double outline_diameter(const Vec3& centre) const;
  double pressure_inside(const ParticleStore& particles, const DropletFields& fields);
  bool ruptured(const Vec3& centre);
  void record(double time, std::span<const double> values);
  std::optional<std::string> rupture_caveat() const;

  DropletOptions options_;
  ShellRupture rupture_test_;
  ShellRing ring_test_;
  // 2D: whether the shell's intact particles closed round the centroid at the first sample; the
  // shell has ruptured when they no longer do (and counts as such only if they did).
  bool ring_checked_ = false;
  bool ring_closed_ = false;
  // The shell's labelled surfaces, by particle id; ids absent are ShellSurface::none.
  std::unordered_map<std::int64_t, ShellSurface> surface_of_;
  bool labelled_ = false;
  bool labelled_on_resume_ = false;  // after replayed rows, not at the run's first sample
  double labelled_at_ = 0.0;         // [s]
  // The shell's particles at a sample (kept between samples).
  std::vector<Vec3> shell_position_;
  std::vector<double> shell_damage_;
  std::vector<ShellSurface> shell_surface_;
  double shell_volume_ = 0.0;  // [m^d]
  // (pressure, volume) of the particles inside the shell at a sample (kept between samples).
  std::vector<std::pair<double, double>> inside_pressure_;
  // The history, a function of the sampled rows.
  bool sampled_ = false;
  double last_time_ = 0.0;
  double first_diameter_ = 0.0;
  double ratio_max_ = std::numeric_limits<double>::quiet_NaN();
  std::optional<Rupture> rupture_;
  std::optional<NearestSample> after_rupture_;
};

}  // namespace partimix::analysis
