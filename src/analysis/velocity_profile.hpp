#pragma once
// Velocity profile along a line (docs/mixing.md, "Velocity profile"): the segment from `start` to
// `end` (length L, unit direction e) is cut into n equal bins; a material particle at x with
// s = (x - start) . e in [0, L] and distance |x - start - s e| <= width/2 from the line falls in
// bin floor(s n / L) (s = L in the last). Each bin reports the number mean over its particles of
// v . d (d the chosen unit direction) or of the speed |v|; NaN when the bin is empty. Bin b is
// centred at start + (b + 1/2) (L/n) e.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"

namespace partimix::analysis {

class VelocityProfile final : public Analysis {
 public:
  // Throws std::invalid_argument unless start != end, bins >= 1, width > 0 and (for a
  // component) the direction is finite and non-zero.
  explicit VelocityProfile(const ProfileLine& line);
  // velocity_profile_0 ... velocity_profile_<n-1> [m/s].
  std::vector<Column> columns() const override;
  void sample(const ParticleStore& particles, double time, std::span<double> values) override;
  void replay(double time, std::span<const double> values) override;
  // velocity_profile_<b>_final: the last sample's value of each bin that was not empty.
  void add_figures(Figures& figures) const override;

 private:
  ProfileLine line_;
  Vec3 axis_;                         // e
  double length_;                     // L
  Vec3 direction_;                    // d (unit), when not the speed
  std::vector<double> sums_;          // per bin, sized at set-up
  std::vector<std::int64_t> counts_;  // per bin
  std::vector<double> last_;          // per bin, the last sample (NaN before the first)
};

}  // namespace partimix::analysis
