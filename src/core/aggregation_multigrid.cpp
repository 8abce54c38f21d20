#include "core/aggregation_multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace partimix {

namespace {

using Matrix = AggregationMultigrid::Matrix;
using Vector = AggregationMultigrid::Vector;
using Index = Eigen::Index;

// docs/sph.md, "The pressure solve": the strength threshold, the size at which the levels stop,
// the largest coarsest level solved directly (and the sweeps that stand in above it), the
// weight of the one Jacobi sweep before and after the coarse step, and the coarse step's
// over-correction.
constexpr double kStrength = 0.5;
constexpr Index kCoarsestSize = 500;
constexpr std::size_t kMaxLevels = 12;
constexpr Index kLargestDirectSize = 20000;
constexpr int kStalledSweeps = 10;
constexpr double kJacobiWeight = 0.9;
constexpr double kOverCorrection = 1.8;
// The finest operator's off-diagonal entries below this fraction of their row's largest are
// lumped onto the diagonal for the V-cycle (BiCGSTAB keeps the whole matrix).
constexpr double kLumpedFraction = 0.3;

// 1 / d, and 0 where d = 0: the Jacobi sweeps leave an unknown without a diagonal unchanged.
Vector safe_inverse(const Vector& diagonal) {
  return diagonal.unaryExpr([](double d) { return d != 0.0 ? 1.0 / d : 0.0; });
}

// j is strongly coupled to i when -a_ij is at least kStrength of the row's largest -a_ik.
template <class Fn>
void for_each_strong(const Matrix& a, Index i, Fn&& fn) {
  double largest = 0.0;
  for (Matrix::InnerIterator it(a, i); it; ++it) {
    if (it.col() != i)
      largest = std::max(largest, -it.value());
  }
  if (largest <= 0.0)
    return;
  for (Matrix::InnerIterator it(a, i); it; ++it) {
    if (it.col() != i && -it.value() >= kStrength * largest)
      fn(it.col());
  }
}

// The three passes of Vanek et al. (1996): whole neighbourhoods that are still free become
// aggregates; the rest join an aggregate one of their strong neighbours is in; what is left
// groups with its free strong neighbours. Returns the number of aggregates.
int aggregate(const Matrix& a, std::vector<int>& of) {
  const Index n = a.rows();
  of.assign(static_cast<std::size_t>(n), -1);
  int count = 0;
  for (Index i = 0; i < n; ++i) {
    bool free = of[static_cast<std::size_t>(i)] < 0;
    for_each_strong(a, i, [&](Index j) { free = free && of[static_cast<std::size_t>(j)] < 0; });
    if (!free)
      continue;
    of[static_cast<std::size_t>(i)] = count;
    for_each_strong(a, i, [&](Index j) { of[static_cast<std::size_t>(j)] = count; });
    ++count;
  }
  std::vector<int> joined = of;
  for (Index i = 0; i < n; ++i) {
    if (of[static_cast<std::size_t>(i)] >= 0)
      continue;
    for_each_strong(a, i, [&](Index j) {
      if (joined[static_cast<std::size_t>(i)] < 0)
        joined[static_cast<std::size_t>(i)] = of[static_cast<std::size_t>(j)];
    });
  }
  of.swap(joined);
  for (Index i = 0; i < n; ++i) {
    if (of[static_cast<std::size_t>(i)] >= 0)
      continue;
    of[static_cast<std::size_t>(i)] = count;
    for_each_strong(a, i, [&](Index j) {
      if (of[static_cast<std::size_t>(j)] < 0)
        of[static_cast<std::size_t>(j)] = count;
    });
    ++count;
  }
  return count;
}

// P^T A P with P_iI = 1 when unknown i is in aggregate I: row I sums the rows of its members,
// column j going to of[j]. Built row by row (the members listed by a counting sort, a row's
// columns gathered through `slot` and sorted), without a global sort of triplets.
Matrix galerkin(const Matrix& a, const std::vector<int>& of, int count) {
  const auto coarse_count = static_cast<std::size_t>(count);
  std::vector<int> first(coarse_count + 1, 0);
  for (const int aggregate : of)
    ++first[static_cast<std::size_t>(aggregate) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<int> members(of.size());
  std::vector<int> next(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < of.size(); ++i)
    members[static_cast<std::size_t>(next[static_cast<std::size_t>(of[i])]++)] =
        static_cast<int>(i);

  Matrix coarse(count, count);
  std::vector<int> slot_row(coarse_count, -1);  // the row whose entry `slot` points at
  std::vector<std::size_t> slot(coarse_count);
  std::vector<std::pair<Index, double>> row_entries;
  for (std::size_t row = 0; row < coarse_count; ++row) {
    row_entries.clear();
    for (int m = first[row]; m < first[row + 1]; ++m) {
      for (Matrix::InnerIterator it(a, members[static_cast<std::size_t>(m)]); it; ++it) {
        const auto column = static_cast<std::size_t>(of[static_cast<std::size_t>(it.col())]);
        if (slot_row[column] != static_cast<int>(row)) {
          slot_row[column] = static_cast<int>(row);
          slot[column] = row_entries.size();
          row_entries.emplace_back(static_cast<Index>(column), it.value());
        } else {
          row_entries[slot[column]].second += it.value();
        }
      }
    }
    std::sort(row_entries.begin(), row_entries.end());
    coarse.startVec(static_cast<Index>(row));
    for (const auto& [column, value] : row_entries)
      coarse.insertBack(static_cast<Index>(row), column) = value;
  }
  coarse.finalize();
  return coarse;
}

// r = b - A x, rows in parallel.
void residual(const Matrix& a, const Vector& x, const Vector& b, Vector& r) {
  const Index n = a.rows();
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    double sum = b[i];
    for (Matrix::InnerIterator it(a, i); it; ++it)
      sum -= it.value() * x[it.col()];
    r[i] = sum;
  }
}

}  // namespace

AggregationMultigrid::Matrix lump_weak_couplings(const AggregationMultigrid::Matrix& a,
                                                 double fraction) {
  Matrix kept(a.rows(), a.cols());
  kept.reserve(a.nonZeros());
  std::vector<std::pair<Index, double>> row_entries;
  for (Index i = 0; i < a.rows(); ++i) {
    double largest = 0.0;
    for (Matrix::InnerIterator it(a, i); it; ++it) {
      if (it.col() != i)
        largest = std::max(largest, std::abs(it.value()));
    }
    row_entries.clear();
    double lumped = 0.0;
    for (Matrix::InnerIterator it(a, i); it; ++it) {
      if (it.col() != i && std::abs(it.value()) < fraction * largest)
        lumped += it.value();
      else
        row_entries.emplace_back(it.col(), it.value());
    }
    if (lumped != 0.0 && std::none_of(row_entries.begin(), row_entries.end(),
                                      [i](const auto& entry) { return entry.first == i; })) {
      row_entries.emplace_back(i, 0.0);
      std::sort(row_entries.begin(), row_entries.end());
    }
    kept.startVec(i);
    for (const auto& [column, value] : row_entries)
      kept.insertBack(i, column) = column == i ? value + lumped : value;
  }
  kept.finalize();
  return kept;
}

void AggregationMultigrid::setup(Matrix a) {
  a = lump_weak_couplings(a, kLumpedFraction);
  levels_.clear();
  coarsest_.reset();
  while (true) {
    Level& level = levels_.emplace_back();
    level.a = std::move(a);
    level.a.makeCompressed();
    const Index n = level.a.rows();
    level.inverse_diagonal = safe_inverse(level.a.diagonal());
    level.x.resize(n);
    level.b.resize(n);
    level.r.resize(n);
    if (n <= kCoarsestSize || levels_.size() == kMaxLevels)
      break;
    const int count = aggregate(level.a, level.aggregate);
    if (count >= n)
      break;
    a = galerkin(level.a, level.aggregate, count);
  }
  if (levels_.back().a.rows() > kLargestDirectSize)
    return;
  coarsest_ = std::make_unique<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
  coarsest_->compute(Eigen::SparseMatrix<double>(levels_.back().a));
  // A failed factorisation must not be solved with (Eigen reads past its arrays): the sweeps
  // stand in, and BiCGSTAB judges whether the system itself can be solved.
  if (coarsest_->info() != Eigen::Success)
    coarsest_.reset();
}

// The coarsest level directly, or, when the aggregation stalled above kLargestDirectSize
// unknowns (a matrix without strong couplings) or the factorisation failed, by Jacobi sweeps.
void AggregationMultigrid::solve_coarsest(const Level& l) const {
  if (coarsest_) {
    l.x = coarsest_->solve(l.b);
    return;
  }
  l.x = kJacobiWeight * l.inverse_diagonal.cwiseProduct(l.b);
  for (int sweep = 1; sweep < kStalledSweeps; ++sweep) {
    residual(l.a, l.x, l.b, l.r);
    l.x += kJacobiWeight * l.inverse_diagonal.cwiseProduct(l.r);
  }
}

// One V-cycle on levels_[level] for its b, into its x.
void AggregationMultigrid::cycle(std::size_t level) const {
  const Level& l = levels_[level];
  if (level + 1 == levels_.size()) {
    solve_coarsest(l);
    return;
  }
  l.x = kJacobiWeight * l.inverse_diagonal.cwiseProduct(l.b);  // one sweep from x = 0
  residual(l.a, l.x, l.b, l.r);
  const Level& next = levels_[level + 1];
  next.b.setZero();
  for (Index i = 0; i < l.a.rows(); ++i)
    next.b[l.aggregate[static_cast<std::size_t>(i)]] += l.r[i];
  cycle(level + 1);
  for (Index i = 0; i < l.a.rows(); ++i)
    l.x[i] += kOverCorrection * next.x[l.aggregate[static_cast<std::size_t>(i)]];
  residual(l.a, l.x, l.b, l.r);
  l.x += kJacobiWeight * l.inverse_diagonal.cwiseProduct(l.r);
}

AggregationMultigrid::Vector AggregationMultigrid::solve(const Vector& b) const {
  levels_.front().b = b;
  cycle(0);
  return levels_.front().x;
}

}  // namespace partimix
