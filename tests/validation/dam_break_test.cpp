// 2D dam break: surge-front position against experiments.
//
// Data (front position Z = x / a against T = t sqrt(2 g / a), column width a, height 2a):
// - Martin, J. C. and Moyce, W. J. (1952), "Part IV. An experimental study of the collapse of
//   liquid columns on a rigid horizontal plane", Phil. Trans. R. Soc. Lond. A 244, 312-324,
//   figure 3, n^2 = 2, a = 2.25 in (values as digitised in the PySPH examples).
// - Koshizuka, S. and Oka, Y. (1996), "Moving-particle semi-implicit method for fragmentation
//   of incompressible fluid", Nucl. Sci. Eng. 123, 421-434 (a = 0.146 m).
// Set-up: Koshizuka and Oka's tank (a = 0.146 m, tank 4a long), water, dp = a / 40, h = 1.5 dp,
// Wendland C2, Tait EOS, c0 = 20 sqrt(g 2a), Fourtakas delta-SPH, no artificial viscosity; and
// the same with the incompressible scheme (projection, Fickian shifting, flow CFL 0.1). No fluid
// particle may pass the floor.
//
// Tolerance: the simulated front, weakly compressible and incompressible, within 20% of Martin
// and Moyce at each of their points up to T = 2.6 (the far wall is reached near T = 2.9).
// Experimental fronts lag inviscid simulations by 10-20% over this range: the gate takes a
// finite time to clear the column and the thin tip feels floor friction and surface tension that
// the simulation does not have, so published WCSPH and VOF fronts run ahead of both data sets
// (docs/validation.md gives the deviations we measure, +13% to +18% against Martin and Moyce and
// up to +22% against Koshizuka and Oka, and the delay of the start that removes them).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/front_position.hpp"
#include "app/simulation.hpp"
#include "validation/case_factory.hpp"
#include "validation/martin_moyce.hpp"

namespace partimix {
namespace {

using Point = testing_cases::SurgePoint;
using testing_cases::kMartinMoyce;

const std::vector<Point> kKoshizukaOka = {{0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505},
                                          {1.537, 1.892}, {1.935, 2.241}, {2.323, 2.615},
                                          {2.719, 3.003}};

bool is_martin_moyce(const Point& point) {
  return std::find_if(kMartinMoyce.begin(), kMartinMoyce.end(),
                      [&](const Point& p) { return p.T == point.T; }) != kMartinMoyce.end();
}

// The front Z = x / a at each point's T (points sorted by T); no fluid particle may be deeper
// than `below` under the floor's surface (y = 0) at any of them.
std::vector<double> surge_front(const io::Case& c, double a, const std::vector<Point>& points,
                                double below) {
  app::Simulation sim = app::build_simulation(c);
  analysis::FrontPosition front(0);
  const double time_scale = std::sqrt(2.0 * 9.81 / a);
  std::vector<double> fronts;
  double t = 0.0;
  for (const Point& point : points) {
    const double target = point.T / time_scale;
    while (t < target - 1e-12) {
      const double dt = std::min(sim.methods[0].solver->stable_dt(), target - t);
      sim.methods[0].solver->step(dt);
      t += dt;
    }
    double x = 0.0;
    front.sample(sim.methods[0].solver->particles(), t, std::span<double>(&x, 1));
    fronts.push_back(x / a);
    const auto& particles = sim.methods[0].solver->particles();
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (particles.is_fluid(i)) {
        EXPECT_GT(particles.position()[i].y(), -below) << "fluid below the floor, T = " << point.T;
      }
    }
  }
  return fronts;
}

// Both schemes against the experiments, and against each other: the incompressible scheme's
// free surface (p = 0 rows, docs/sph.md "Incompressible SPH") moves the front as the weakly-
// compressible pressure does. Measured at a/40: the two within 1.0% of each other at the Martin
// and Moyce points and 1.8% at all eleven (docs/validation.md), so the test's 3% would catch a
// surface condition that holds the front back or lets it run.
TEST(DamBreak, SurgeFrontFollowsMartinAndMoyceWithEitherScheme) {
  const double a = 0.146;
  std::vector<Point> all = kMartinMoyce;
  all.insert(all.end(), kKoshizukaOka.begin(), kKoshizukaOka.end());
  std::sort(all.begin(), all.end(), [](const Point& p, const Point& q) { return p.T < q.T; });
  const io::Case weakly_compressible = testing_cases::dam_break_2d(a, a / 40.0);
  io::Case incompressible = testing_cases::dam_break_2d(a, a / 40.0);
  testing_cases::sph_of(incompressible).config.scheme = "incompressible";
  testing_cases::sph_of(incompressible).config.shifting.model = "fickian";
  const std::vector<double> wcsph = surge_front(weakly_compressible, a, all, 0.0);
  // The incompressible front's leading particle, a free-surface particle (p = 0), skims the
  // floor up to 0.10 dp below its surface (0.13 dp at a/50; measured on frames every 2 ms,
  // docs/sph.md "Incompressible SPH"): nothing but the wall's pressure holds it, and that is
  // extrapolated from the fluid's, zero there. The bound is half-way to the first layer of wall
  // particles, where the fluid would pass among them.
  const std::vector<double> isph = surge_front(incompressible, a, all, 0.25 * a / 40.0);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const bool martin_moyce = is_martin_moyce(all[k]);
    std::printf(
        "dam break T = %.3f: Z = %.3f (weakly compressible), %.3f (incompressible), %s "
        "%.3f\n",
        all[k].T, wcsph[k], isph[k], martin_moyce ? "Martin-Moyce" : "Koshizuka-Oka", all[k].Z);
    EXPECT_NEAR(isph[k] / wcsph[k], 1.0, 0.03) << "T = " << all[k].T;
    if (martin_moyce) {
      EXPECT_LT(std::abs(wcsph[k] / all[k].Z - 1.0), 0.20) << "T = " << all[k].T;
      EXPECT_LT(std::abs(isph[k] / all[k].Z - 1.0), 0.20) << "T = " << all[k].T;
    }
  }
}

}  // namespace
}  // namespace partimix
