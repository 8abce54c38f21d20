// 2D dam break: surge-front position against experiments.
//
// Data (front position Z = x / a against T = t sqrt(2 g / a), column width a, height 2a):
// - Martin, J. C. and Moyce, W. J. (1952), "Part IV. An experimental study of the collapse of
//   liquid columns on a rigid horizontal plane", Phil. Trans. R. Soc. Lond. A 244, 312-324,
//   figure 3, n^2 = 2, a = 2.25 in (values as digitised in the PySPH examples).
// - Koshizuka, S. and Oka, Y. (1996), "Moving-particle semi-implicit method for fragmentation
//   of incompressible fluid", Nucl. Sci. Eng. 123, 421-434 (a = 0.146 m).
// Set-up: Koshizuka and Oka's tank (a = 0.146 m, tank 4a long), water, dp = a / 40, h = 1.5 dp,
// Wendland C2, Tait EOS, c0 = 20 sqrt(g 2a), Fourtakas delta-SPH, no artificial viscosity.
// No fluid particle may pass the floor.
//
// Tolerance: the simulated front within 20% of Martin and Moyce at each of their points up to
// T = 2.6 (the far wall is reached near T = 2.9). Experimental fronts lag inviscid simulations
// by 10-20% over this range: the gate takes a finite time to clear the column and the thin tip
// feels floor friction and surface tension that the simulation does not have, so published
// WCSPH and VOF fronts run ahead of both data sets (docs/validation.md gives the deviations we
// measure, +13% to +17% against Martin and Moyce and up to +22% against Koshizuka and Oka).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/front_position.hpp"
#include "app/simulation.hpp"
#include "validation/case_factory.hpp"

namespace partimix {
namespace {

struct Point {
  double T;
  double Z;
};

const std::vector<Point> kMartinMoyce = {
    {0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995}};

const std::vector<Point> kKoshizukaOka = {{0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505},
                                          {1.537, 1.892}, {1.935, 2.241}, {2.323, 2.615},
                                          {2.719, 3.003}};

TEST(DamBreak, SurgeFrontFollowsMartinAndMoyce) {
  const double a = 0.146;
  const double g = 9.81;
  app::Simulation sim = app::build_simulation(testing_cases::dam_break_2d(a, a / 40.0));
  analysis::FrontPosition front(0);
  const double time_scale = std::sqrt(2.0 * g / a);
  std::vector<Point> all = kMartinMoyce;
  all.insert(all.end(), kKoshizukaOka.begin(), kKoshizukaOka.end());
  std::sort(all.begin(), all.end(), [](const Point& p, const Point& q) { return p.T < q.T; });

  double t = 0.0;
  for (const Point& point : all) {
    const double target = point.T / time_scale;
    while (t < target - 1e-12) {
      const double dt = std::min(sim.methods[0].solver->stable_dt(), target - t);
      sim.methods[0].solver->step(dt);
      t += dt;
    }
    double x = 0.0;
    front.sample(sim.methods[0].solver->particles(), t, std::span<double>(&x, 1));
    const double deviation = (x / a - point.Z) / point.Z;
    const bool martin_moyce =
        std::find_if(kMartinMoyce.begin(), kMartinMoyce.end(),
                     [&](const Point& p) { return p.T == point.T; }) != kMartinMoyce.end();
    std::printf("dam break T = %.3f: Z = %.3f, %s %.3f, deviation %+.3f\n", point.T, x / a,
                martin_moyce ? "Martin-Moyce" : "Koshizuka-Oka", point.Z, deviation);
    for (std::size_t i = 0; i < sim.methods[0].solver->particles().size(); ++i) {
      if (sim.methods[0].solver->particles().is_fluid(i)) {
        ASSERT_GT(sim.methods[0].solver->particles().position()[i].y(), 0.0)
            << "fluid below the floor";
      }
    }
    if (martin_moyce) {
      EXPECT_LT(std::abs(deviation), 0.20) << "T = " << point.T;
    }
  }
}

}  // namespace
}  // namespace partimix
