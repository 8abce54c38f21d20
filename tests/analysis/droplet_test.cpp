// The droplet analysis (docs/multi-material-sph.md, "The scheme", droplet measurements;
// docs/case-reference.md, "analyses", droplet) on a 2D droplet built by hand, spacing 1 m: a disc
// of gas (lattice points at r <= 3, vapour and air alternating), liquid round it (3 < r <= 9.5)
// and a shell of four rings of radii 10.5 to 13.5 (the ring of shell_rupture_test). Per particle:
// liquid m = 800 kg, rho = 800 kg/m^3 (volume 1), p = 200 Pa; shell m = rho = 1000 (volume 1),
// p = 5e4 Pa (left out of the pressure); vapour m = 1, rho = 2 (volume 0.5), p = 1000 Pa,
// T = 900 K; air m = 2, rho = 4 (volume 0.5), p = 600 Pa, T = 1500 K. With n_s shell particles
// (volume n_s): D = 2 (13.5 + t / 2), t = n_s / (pi (13.5 + 10.5)) - 3, the layer that makes the
// ring between 10.5 - t/2 and 13.5 + t/2 hold the shell; the pressure is the volume-weighted
// median, the liquid's 200 Pa (the mean, which the gas would move, is not); the gas temperature
// (900 n_v + 2 1500 n_a) / (n_v + 2 n_a) (by mass, not by volume, which would weigh them 1:1).
// Scaling every position by s and every density by 1 / s^2 gives D / D0 = s. A radial crack of
// damage 1 through all four rings ruptures the shell, also after the particles are reordered
// (the surfaces are kept by id); a crack one ring short does not; so does moving three
// particles of each ring far off without any damage (the shell parts), unless the shell was
// already open at the first sample. Tolerance 1e-12: round-off.
#include "analysis/droplet.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;
using ::testing::HasSubstr;

constexpr double kTight = 1e-12;
constexpr int kLiquid = 0;
constexpr int kShell = 1;
constexpr int kVapour = 2;
constexpr int kAir = 3;
constexpr int kLayers = 4;
constexpr double kInnerRadius = 10.5;  // [m]

DropletOptions droplet_options() {
  DropletOptions options;
  options.shell = kShell;
  options.gas = {kVapour, kAir};
  options.link = 1.5;
  options.dimensions = 2;
  return options;
}

// The column `name` of a row of `droplet`.
double column(const Droplet& droplet, const std::vector<double>& row, const std::string& name) {
  const std::vector<Column> columns = droplet.columns();
  const auto at = std::ranges::find(columns, name, &Column::name);
  return row.at(static_cast<std::size_t>(at - columns.begin()));
}

class DropletStore : public ::testing::Test {
 protected:
  DropletStore()
      : material_(store_.add_integer("material", "")),
        density_(store_.add_scalar("density", "kg/m^3")),
        pressure_(store_.add_scalar("pressure", "Pa")),
        temperature_(store_.add_scalar("temperature", "K")),
        damage_(store_.add_scalar("damage", "")),
        layer_(store_.add_integer("layer", "")) {
    add_core();
    add_shell();
  }

  // A particle of `material` at x with its mass, density, pressure and temperature.
  void add(const Vec3& x, int material, double mass, double density, double pressure,
           double temperature) {
    const std::size_t i = add_particle(store_, ParticleKind::fluid, x);
    store_.mass()[i] = mass;
    material_.values[i] = material;
    density_.values[i] = density;
    pressure_.values[i] = pressure;
    temperature_.values[i] = temperature;
    layer_.values[i] = -1;
    count_[static_cast<std::size_t>(material)] += 1.0;
  }

  // The gas disc and the liquid round it, on the unit lattice.
  void add_core() {
    for (int ix = -9; ix <= 9; ++ix) {
      for (int iy = -9; iy <= 9; ++iy) {
        const Vec3 x(ix, iy, 0.0);
        const double r = x.norm();
        if (r <= 3.0 && (ix + iy) % 2 == 0)
          add(x, kVapour, 1.0, 2.0, 1000.0, 900.0);
        else if (r <= 3.0)
          add(x, kAir, 2.0, 4.0, 600.0, 1500.0);
        else if (r <= 9.5)
          add(x, kLiquid, 800.0, 800.0, 200.0, 300.0);
      }
    }
  }

  // Four rings of shell, about one spacing apart round each; the first particle of each at
  // angle 0.
  void add_shell() {
    for (int layer = 0; layer < kLayers; ++layer) {
      const double radius = kInnerRadius + layer;
      const int count = static_cast<int>(std::round(2.0 * std::numbers::pi * radius));
      for (int k = 0; k < count; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / count;
        add(radius * Vec3(std::cos(angle), std::sin(angle), 0.0), kShell, 1000.0, 1000.0, 5.0e4,
            350.0);
        layer_.values.back() = layer;
      }
    }
  }

  // Damage 1 on the shell particles at angle 0 (y = 0, x > 0) of the innermost `layers` rings.
  void crack(int layers) {
    for (std::size_t i = 0; i < store_.size(); ++i) {
      const Vec3& x = store_.position()[i];
      const bool on_line = x.y() == 0.0 && x.x() > 0.0;
      if (on_line && layer_.values[i] >= 0 && layer_.values[i] < layers)
        damage_.values[i] = 1.0;
    }
  }

  // Moves the shell particles near angle 0 (x > 0, |y| < 1.2: three of each ring) 100 m along
  // x, undamaged: the shell parts with a gap of four spacings.
  void part() {
    for (std::size_t i = 0; i < store_.size(); ++i) {
      Vec3& x = store_.position()[i];
      if (layer_.values[i] >= 0 && x.x() > 0.0 && std::abs(x.y()) < 1.2)
        x.x() += 100.0;
    }
  }

  // Every position times s and every density over s^2: each volume m / rho times s^2.
  void scale(double s) {
    for (std::size_t i = 0; i < store_.size(); ++i) {
      store_.position()[i] *= s;
      density_.values[i] /= s * s;
    }
  }

  // Every pressure inside the shell set to p.
  void set_inside_pressure(double p) {
    for (std::size_t i = 0; i < store_.size(); ++i) {
      if (material_.values[i] != kShell)
        pressure_.values[i] = p;
    }
  }

  double count(int material) const { return count_[static_cast<std::size_t>(material)]; }

  ParticleStore store_;
  Field<std::int32_t>& material_;
  Field<double>& density_;
  Field<double>& pressure_;
  Field<double>& temperature_;
  Field<double>& damage_;
  Field<std::int32_t>& layer_;  // the shell's ring from the inside, 0 to 3; -1 off the shell
  std::vector<double> count_ = std::vector<double>(4, 0.0);
};

TEST_F(DropletStore, FirstSampleMeasuresTheDropletByHand) {
  Droplet droplet(droplet_options());
  const std::vector<double> row = sample_once(droplet, store_, 0.0);
  const double n_l = count(kLiquid);
  const double n_v = count(kVapour);
  const double n_a = count(kAir);
  const double layer = count(kShell) / (std::numbers::pi * 24.0) - 3.0;
  EXPECT_NEAR(column(droplet, row, "diameter"), 2.0 * (13.5 + 0.5 * layer), kTight * 100.0);
  EXPECT_NEAR(layer, 1.0, 0.02);
  EXPECT_DOUBLE_EQ(column(droplet, row, "diameter_ratio"), 1.0);
  const double mean =
      (200.0 * n_l + 0.5 * (1000.0 * n_v + 600.0 * n_a)) / (n_l + 0.5 * (n_v + n_a));
  EXPECT_EQ(column(droplet, row, "pressure_above_ambient"), 200.0);
  EXPECT_GT(mean, 210.0);
  const double temperature = (900.0 * n_v + 2.0 * 1500.0 * n_a) / (n_v + 2.0 * n_a);
  EXPECT_NEAR(column(droplet, row, "gas_temperature"), temperature, kTight * temperature);
  EXPECT_EQ(column(droplet, row, "damage_max"), 0.0);
  EXPECT_EQ(column(droplet, row, "ruptured"), 0.0);
  EXPECT_GT(n_v, 0.0);
  EXPECT_GT(n_a, 0.0);
}

TEST_F(DropletStore, ScalingTheDropletScalesTheDiameterRatio) {
  Droplet droplet(droplet_options());
  sample_once(droplet, store_, 0.0);
  scale(1.3);
  const std::vector<double> row = sample_once(droplet, store_, 0.1);
  EXPECT_NEAR(column(droplet, row, "diameter_ratio"), 1.3, kTight);
  Figures figures;
  droplet.add_figures(figures);
  EXPECT_NEAR(figures.at("diameter_ratio_max"), 1.3, kTight);
}

TEST_F(DropletStore, DamageMaxIsTheShells) {
  Droplet droplet(droplet_options());
  damage_.values.back() = 0.7;
  damage_.values.front() = 0.9;  // a liquid particle: not shell
  EXPECT_EQ(column(droplet, sample_once(droplet, store_, 0.0), "damage_max"), 0.7);
}

TEST_F(DropletStore, CrackThroughAllLayersRuptures) {
  Droplet droplet(droplet_options());
  sample_once(droplet, store_, 0.0);
  crack(kLayers - 1);
  EXPECT_EQ(column(droplet, sample_once(droplet, store_, 0.1), "ruptured"), 0.0);
  crack(kLayers);
  const std::vector<double> row = sample_once(droplet, store_, 0.2);
  EXPECT_EQ(column(droplet, row, "ruptured"), 1.0);
  EXPECT_EQ(column(droplet, row, "damage_max"), 1.0);
}

TEST_F(DropletStore, ShellPartedWithoutDamageRuptures) {
  Droplet droplet(droplet_options());
  sample_once(droplet, store_, 0.0);
  part();
  const std::vector<double> row = sample_once(droplet, store_, 0.1);
  EXPECT_EQ(column(droplet, row, "ruptured"), 1.0);
  EXPECT_EQ(column(droplet, row, "damage_max"), 0.0);
}

// A shell open from the first sample (not a closed droplet) is not found to open later.
TEST_F(DropletStore, ShellOpenFromTheFirstSampleIsNotARupture) {
  part();
  Droplet droplet(droplet_options());
  EXPECT_EQ(column(droplet, sample_once(droplet, store_, 0.0), "ruptured"), 0.0);
  EXPECT_EQ(column(droplet, sample_once(droplet, store_, 0.1), "ruptured"), 0.0);
}

TEST_F(DropletStore, SurfacesAreKeptThroughAReordering) {
  Droplet droplet(droplet_options());
  sample_once(droplet, store_, 0.0);
  std::vector<std::uint32_t> reversed(store_.size());
  for (std::size_t k = 0; k < reversed.size(); ++k)
    reversed[k] = static_cast<std::uint32_t>(reversed.size() - 1 - k);
  store_.reorder(reversed);
  crack(kLayers);
  EXPECT_EQ(column(droplet, sample_once(droplet, store_, 0.1), "ruptured"), 1.0);
}

// Samples at t = 0 and 0.05 s, the rupture at 0.1 s, then 0.15, 0.18, 0.23 s: the sample nearest
// 0.2 s is that at 0.18 s, known once the one at 0.23 s has come.
TEST_F(DropletStore, RuptureTimeAndThePressuresAfterIt) {
  Droplet droplet(droplet_options());
  sample_once(droplet, store_, 0.0);
  sample_once(droplet, store_, 0.05);
  Figures before;
  Caveats not_yet;
  droplet.add_figures(before);
  droplet.add_caveats(not_yet);
  EXPECT_FALSE(before.contains("rupture_time"));
  EXPECT_THAT(not_yet.at("rupture_time"), HasSubstr("had not ruptured"));
  crack(kLayers);
  const std::vector<double> times{0.1, 0.15, 0.18, 0.23};
  const std::vector<double> pressures{700.0, 650.0, 610.0, 560.0};
  for (std::size_t k = 0; k < times.size(); ++k) {
    set_inside_pressure(pressures[k]);
    sample_once(droplet, store_, times[k]);
    if (k == 2) {
      Figures early;
      Caveats caveats;
      droplet.add_figures(early);
      droplet.add_caveats(caveats);
      EXPECT_FALSE(early.contains("pressure_after_rupture"));
      EXPECT_THAT(caveats.at("pressure_after_rupture"), HasSubstr("before rupture_time"));
    }
  }
  Figures figures;
  Caveats caveats;
  droplet.add_figures(figures);
  droplet.add_caveats(caveats);
  EXPECT_EQ(figures.at("rupture_time"), 0.1);
  EXPECT_EQ(figures.unit("rupture_time"), "s");
  EXPECT_NEAR(figures.at("pressure_at_rupture"), 700.0, kTight * 700.0);
  EXPECT_NEAR(figures.at("pressure_after_rupture"), 610.0, kTight * 610.0);
  EXPECT_EQ(figures.at("diameter_ratio_max"), 1.0);
  EXPECT_TRUE(caveats.empty());
}

// With after_rupture 0.05 s the second pressure is that of the sample nearest 0.15 s.
TEST_F(DropletStore, PressureAfterRuptureTakesItsDelay) {
  DropletOptions options = droplet_options();
  options.after_rupture = 0.05;
  Droplet droplet(options);
  sample_once(droplet, store_, 0.0);
  crack(kLayers);
  const std::vector<double> times{0.1, 0.14, 0.17};
  const std::vector<double> pressures{700.0, 650.0, 610.0};
  for (std::size_t k = 0; k < times.size(); ++k) {
    set_inside_pressure(pressures[k]);
    sample_once(droplet, store_, times[k]);
  }
  Figures figures;
  droplet.add_figures(figures);
  EXPECT_NEAR(figures.at("pressure_after_rupture"), 650.0, kTight * 650.0);
  options.after_rupture = 0.0;
  EXPECT_THROW(Droplet{options}, std::invalid_argument);
}

// A resumed run replays the rows: its history (D0, the rupture) goes on as if never stopped; its
// surfaces are labelled afresh, which the caveat of rupture_time says when it ruptures later.
TEST_F(DropletStore, ReplayKeepsTheHistory) {
  Droplet first(droplet_options());
  std::vector<std::vector<double>> rows{sample_once(first, store_, 0.0)};
  scale(1.1);
  rows.push_back(sample_once(first, store_, 0.1));
  Droplet resumed(droplet_options());
  resumed.replay(0.0, rows[0]);
  resumed.replay(0.1, rows[1]);
  crack(kLayers);
  const std::vector<double> row = sample_once(resumed, store_, 0.2);
  EXPECT_NEAR(column(resumed, row, "diameter_ratio"), 1.1, kTight);
  EXPECT_EQ(column(resumed, row, "ruptured"), 1.0);
  Caveats caveats;
  resumed.add_caveats(caveats);
  EXPECT_THAT(caveats.at("rupture_time"), HasSubstr("labelled at t = 0.2 s"));
}

TEST_F(DropletStore, ParticlesOfAnotherSchemeAreARunError) {
  ParticleStore plain;
  add_particle(plain, ParticleKind::fluid, Vec3::Zero());
  Droplet droplet(droplet_options());
  try {
    sample_once(droplet, plain, 0.0);
    FAIL() << "expected a RunError";
  } catch (const RunError& error) {
    EXPECT_THAT(error.what(), HasSubstr("sph.scheme: multi_material"));
  }
}

TEST(Droplet, RefusesOptionsWithoutAShellOrALink) {
  DropletOptions options = droplet_options();
  options.shell = -1;
  EXPECT_THROW(Droplet{options}, std::invalid_argument);
  options = droplet_options();
  options.link = 0.0;
  EXPECT_THROW(Droplet{options}, std::invalid_argument);
  options = droplet_options();
  options.dimensions = 1;
  EXPECT_THROW(Droplet{options}, std::invalid_argument);
}

}  // namespace
}  // namespace partimix::analysis
