#pragma once
// Mixing measures over sampling cells (docs/mixing.md): the uniformity index xi of the seed
// (Hong et al. 2024, eq. (S28)) and the Lacey index M (Lacey 1954). Both are functions of the
// per-cell counts of tracer particles and of all particles; the counts go into a buffer that the
// caller sizes once, so that sampling a run again and again does not allocate.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "analysis/sampling_cells.hpp"
#include "core/vec.hpp"

namespace partimix::analysis {

// What a particle is to the mixing measures.
enum class MixingRole : std::uint8_t {
  ignored = 0,  // not part of the mixture (wall particles, another phase): counted nowhere
  other = 1,    // in the mixture, not a tracer
  tracer = 2,   // a tracer ("red") particle
};

// Per-cell counts for one set of sampling cells. The constructor allocates (at set-up);
// count_cells only overwrites.
struct CellCounts {
  explicit CellCounts(const SamplingCells& cells);
  std::vector<std::int64_t> tracer;  // N_i: tracer particles in cell i
  std::vector<std::int64_t> total;   // tracer and other particles in cell i
};

// Overwrites `counts` with the counts of the particles (positions[k], roles[k]) that lie in
// `cells`. Throws std::invalid_argument when the spans differ in length or `counts` was sized
// for a different number of cells.
void count_cells(const SamplingCells& cells, std::span<const Vec3> positions,
                 std::span<const MixingRole> roles, CellCounts& counts);

// Uniformity index, eq. (S28): xi = sum_i (N_i - Nbar)^2 / ((n - 1) N0^2) over all n cells, empty
// ones included (as the seed counts every cell of its cylinder), with N0 = sum_i N_i and
// Nbar = N0 / n. 0 when every cell holds the same number of tracers, 1/n when all sit in one
// cell. NaN when n < 2 or there is no tracer in the region (N0 = 0).
double uniformity_index(const CellCounts& counts);
double uniformity_index(const SamplingCells& cells, std::span<const Vec3> positions,
                        std::span<const MixingRole> roles, CellCounts& scratch);

// Why a Lacey index is NaN, if it is.
enum class LaceyStatus {
  ok,
  too_few_cells,          // fewer than 2 counted cells: no sample variance
  no_tracer,              // p = 0: S0^2 = 0, nothing to mix
  no_other,               // p = 1: S0^2 = 0, nothing to mix
  one_particle_per_cell,  // nbar = 1: Sr^2 = S0^2, the denominator vanishes
};

// Lacey index and the quantities it is made of (docs/mixing.md).
struct LaceyResult {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double index = nan;  // M = (S0^2 - S^2) / (S0^2 - Sr^2)
  LaceyStatus status = LaceyStatus::too_few_cells;
  int cells = 0;                     // counted cells: those holding at least min_count particles
  double tracer_fraction = nan;      // p = tracers / particles, over the counted cells
  double mean_count = nan;           // nbar = particles / counted cells
  double variance = nan;             // S^2: unweighted sample variance of the cell fractions
  double segregated_variance = nan;  // S0^2 = p (1 - p)
  double random_variance = nan;      // Sr^2 = p (1 - p) / nbar
};

// Lacey index over the cells that hold at least max(min_count, 1) particles. S^2 is the
// unweighted sample variance (divisor: counted cells - 1) of the tracer fraction of each counted
// cell about their unweighted mean: each cell is one sample, as in Lacey's sampling picture, and
// the divisor makes S^2 unbiased when the mean is estimated (Fan, Chen & Watson 1970), so that a
// random mixture with equal cell counts has E[S^2] = Sr^2. index is NaN, and status says why, in
// the degenerate cases of LaceyStatus; the other fields are filled as far as they are defined.
LaceyResult lacey_index(const CellCounts& counts, int min_count);
LaceyResult lacey_index(const SamplingCells& cells, std::span<const Vec3> positions,
                        std::span<const MixingRole> roles, int min_count, CellCounts& scratch);

}  // namespace partimix::analysis
