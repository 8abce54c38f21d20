#include "analysis/mixing_index.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace partimix::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Sums over the counted cells of the Lacey index.
struct CountedCells {
  int cells = 0;
  std::int64_t tracers = 0;
  std::int64_t particles = 0;
  double fraction_sum = 0.0;
};

double tracer_fraction(const CellCounts& counts, std::size_t i) {
  return static_cast<double>(counts.tracer[i]) / static_cast<double>(counts.total[i]);
}

CountedCells sum_counted(const CellCounts& counts, std::int64_t threshold) {
  CountedCells s;
  for (std::size_t i = 0; i < counts.total.size(); ++i) {
    if (counts.total[i] < threshold)
      continue;
    ++s.cells;
    s.tracers += counts.tracer[i];
    s.particles += counts.total[i];
    s.fraction_sum += tracer_fraction(counts, i);
  }
  return s;
}

// S^2 = sum_i (phi_i - phi_mean)^2 / (cells - 1) over the counted cells, phi_mean their unweighted
// mean: unbiased for the mean of the cells' variances, so that E[S^2] = Sr^2 for a random
// mixture (docs/mixing.md). Needs s.cells >= 2.
double cell_fraction_variance(const CellCounts& counts, std::int64_t threshold,
                              const CountedCells& s) {
  const double mean = s.fraction_sum / s.cells;
  double sum = 0.0;
  for (std::size_t i = 0; i < counts.total.size(); ++i) {
    if (counts.total[i] < threshold)
      continue;
    const double deviation = tracer_fraction(counts, i) - mean;
    sum += deviation * deviation;
  }
  return sum / (s.cells - 1);
}

// Decided on integer counts, so that no case that would divide by zero slips through round-off.
LaceyStatus status_of(const CountedCells& s) {
  if (s.cells < 2)
    return LaceyStatus::too_few_cells;
  if (s.tracers == 0)
    return LaceyStatus::no_tracer;
  if (s.tracers == s.particles)
    return LaceyStatus::no_other;
  if (s.particles == s.cells)
    return LaceyStatus::one_particle_per_cell;
  return LaceyStatus::ok;
}

void require_same_cells(const SamplingCells& cells, const CellCounts& counts) {
  const auto n = static_cast<std::size_t>(cells.count());
  if (counts.tracer.size() != n || counts.total.size() != n)
    throw std::invalid_argument("count_cells: the counts were sized for other sampling cells");
}

}  // namespace

CellCounts::CellCounts(const SamplingCells& cells)
    : tracer(static_cast<std::size_t>(cells.count()), 0),
      total(static_cast<std::size_t>(cells.count()), 0) {}

void count_cells(const SamplingCells& cells, std::span<const Vec3> positions,
                 std::span<const MixingRole> roles, CellCounts& counts) {
  if (positions.size() != roles.size())
    throw std::invalid_argument("count_cells: positions and roles differ in length");
  require_same_cells(cells, counts);
  std::fill(counts.tracer.begin(), counts.tracer.end(), 0);
  std::fill(counts.total.begin(), counts.total.end(), 0);
  for (std::size_t k = 0; k < positions.size(); ++k) {
    if (roles[k] == MixingRole::ignored)
      continue;
    const int cell = cells.cell_of(positions[k]);
    if (cell < 0)
      continue;
    ++counts.total[cell];
    if (roles[k] == MixingRole::tracer)
      ++counts.tracer[cell];
  }
}

double uniformity_index(const CellCounts& counts) {
  const std::size_t n = counts.tracer.size();
  const std::int64_t n0 =
      std::accumulate(counts.tracer.begin(), counts.tracer.end(), std::int64_t{0});
  if (n < 2 || n0 == 0)
    return kNaN;
  const double mean = static_cast<double>(n0) / static_cast<double>(n);
  double sum = 0.0;
  for (const std::int64_t count : counts.tracer) {
    const double deviation = static_cast<double>(count) - mean;
    sum += deviation * deviation;
  }
  const double total = static_cast<double>(n0);
  return sum / ((static_cast<double>(n) - 1.0) * total * total);
}

double uniformity_index(const SamplingCells& cells, std::span<const Vec3> positions,
                        std::span<const MixingRole> roles, CellCounts& scratch) {
  count_cells(cells, positions, roles, scratch);
  return uniformity_index(scratch);
}

LaceyResult lacey_index(const CellCounts& counts, int min_count) {
  // A cell without particles has no tracer fraction, whatever min_count says.
  const std::int64_t threshold = std::max(min_count, 1);
  const CountedCells s = sum_counted(counts, threshold);
  LaceyResult r;
  r.cells = s.cells;
  r.status = status_of(s);
  if (s.particles > 0) {
    const double p = static_cast<double>(s.tracers) / static_cast<double>(s.particles);
    r.tracer_fraction = p;
    r.mean_count = static_cast<double>(s.particles) / s.cells;
    r.segregated_variance = p * (1.0 - p);
    r.random_variance = r.segregated_variance / r.mean_count;
  }
  if (s.cells >= 2)
    r.variance = cell_fraction_variance(counts, threshold, s);
  // With 0 < p < 1 and nbar > 1, S0^2 - Sr^2 = p (1 - p) (1 - 1/nbar) > 0.
  if (r.status == LaceyStatus::ok)
    r.index = (r.segregated_variance - r.variance) / (r.segregated_variance - r.random_variance);
  return r;
}

LaceyResult lacey_index(const SamplingCells& cells, std::span<const Vec3> positions,
                        std::span<const MixingRole> roles, int min_count, CellCounts& scratch) {
  count_cells(cells, positions, roles, scratch);
  return lacey_index(scratch, min_count);
}

}  // namespace partimix::analysis
