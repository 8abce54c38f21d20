#pragma once
// Power and Reynolds numbers of an impeller (docs/power.md; the seed's eqs. 25-27, 29-31),
// written as Re = rho V^(2-n) L^n / (K_s k^(n-1)) and Np = P / (rho V^3 L^2) with the scales
//   single axis (rotation): V = N d, L = d    (eqs. 25-27: Re = rho N^(2-n) d^2 / (K_s k^(n-1)),
//                                              Np = P / (rho N^3 d^5))
//   planetary:              V = u_ch = N_G d_G + N_R d_R, L = d_G = 2 e''  (eqs. 29-31)
// with speeds in revolutions per second, k the Metzner-Otto constant (7.54 in the seed) and
// n = 1, K_s = mu for a Newtonian fluid. The series has Re, Np from the rotation power
// |omega_R Gamma_own| (the seed's definition) and Np_total from the body's total mechanical
// power; the summary their means over the last revolutions.
#include <stdexcept>

#include "analysis/analysis.hpp"
#include "analysis/time_average.hpp"

namespace partimix::analysis {

struct PowerScales {
  double velocity = 0.0;  // V [m/s]
  double length = 0.0;    // L [m]
};

// Throws std::invalid_argument for a body that does not turn, a non-positive diameter, or a
// planetary u_ch <= 0.
PowerScales power_scales(const geometry::MotionConfig& motion, double diameter);

double reynolds_number(const FlowScales& fluid, double metzner_otto, const PowerScales& scales);
double power_number(double power, double density, const PowerScales& scales);

class PowerNumber final : public Analysis {
 public:
  explicit PowerNumber(const AnalysisOptions& options);
  std::vector<Column> columns() const override;
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  bool needs_body_forces() const override { return true; }
  void add_figures(Figures& figures) const override;
  void add_caveats(Caveats& caveats) const override;

 private:
  BodyOptions body_;
  double density_;
  PowerScales scales_;
  double reynolds_;
  ColumnHistory history_;
};

}  // namespace partimix::analysis
