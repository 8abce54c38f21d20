#include "core/aggregation_multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace partimix {

namespace {

using Matrix = AggregationMultigrid::Matrix;
using MatrixView = AggregationMultigrid::MatrixView;
using Vector = AggregationMultigrid::Vector;
using Index = Eigen::Index;

// docs/sph.md, "The pressure solve": the strength threshold, the size at which the levels stop
// (and the largest solved by the dense factorisation), the largest coarsest level solved
// directly (and the sweeps that stand in above it), the weight of the one Jacobi sweep before
// and after the coarse step, and the coarse step's over-correction.
constexpr double kStrength = 0.5;
constexpr Index kCoarsestSize = 500;
constexpr std::size_t kMaxLevels = 12;
constexpr Index kLargestDirectSize = 20000;
constexpr int kStalledSweeps = 10;
constexpr double kJacobiWeight = 0.9;
constexpr double kOverCorrection = 1.8;
// An unknown's aggregate while the passes run, and for good where it has no strong coupling.
constexpr int kFree = -1;
constexpr int kIsolated = -2;

Eigen::Map<Vector> as_vector(std::vector<double>& v) {
  return {v.data(), static_cast<Index>(v.size())};
}
Eigen::Map<const Vector> as_vector(const std::vector<double>& v) {
  return {v.data(), static_cast<Index>(v.size())};
}

// j is strongly coupled to i when -a_ij is at least kStrength of the row's largest -a_ik.
template <class Fn>
void for_each_strong(const MatrixView& a, Index i, Fn&& fn) {
  double largest = 0.0;
  for (MatrixView::InnerIterator it(a, i); it; ++it) {
    if (it.col() != i)
      largest = std::max(largest, -it.value());
  }
  if (largest <= 0.0)
    return;
  for (MatrixView::InnerIterator it(a, i); it; ++it) {
    if (it.col() != i && -it.value() >= kStrength * largest)
      fn(it.col());
  }
}

// Row i of `a` lumped (lump_weak_couplings), into `entries` in column order.
template <class MatrixType>
void lump_row(const MatrixType& a, Index i, double fraction,
              std::vector<std::pair<int, double>>& entries) {
  double largest = 0.0;
  for (typename MatrixType::InnerIterator it(a, i); it; ++it) {
    if (it.col() != i)
      largest = std::max(largest, std::abs(it.value()));
  }
  entries.clear();
  double lumped = 0.0;
  for (typename MatrixType::InnerIterator it(a, i); it; ++it) {
    if (it.col() != i && std::abs(it.value()) < fraction * largest)
      lumped += it.value();
    else
      entries.emplace_back(static_cast<int>(it.col()), it.value());
  }
  if (lumped == 0.0)
    return;
  const auto diagonal = std::find_if(entries.begin(), entries.end(),
                                     [i](const auto& entry) { return entry.first == i; });
  if (diagonal != entries.end()) {
    diagonal->second += lumped;
    return;
  }
  entries.emplace_back(static_cast<int>(i), lumped);
  std::sort(entries.begin(), entries.end());
}

// r = b - A x, rows in parallel.
void residual(const MatrixView& a, const std::vector<double>& x, const std::vector<double>& b,
              std::vector<double>& r) {
  const Index n = a.rows();
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    double sum = b[static_cast<std::size_t>(i)];
    for (MatrixView::InnerIterator it(a, i); it; ++it)
      sum -= it.value() * x[static_cast<std::size_t>(it.col())];
    r[static_cast<std::size_t>(i)] = sum;
  }
}

}  // namespace

AggregationMultigrid::Matrix lump_weak_couplings(const AggregationMultigrid::Matrix& a,
                                                 double fraction) {
  Matrix kept(a.rows(), a.cols());
  kept.reserve(a.nonZeros());
  std::vector<std::pair<int, double>> entries;
  for (Index i = 0; i < a.rows(); ++i) {
    lump_row(a, i, fraction, entries);
    kept.startVec(i);
    for (const auto& [column, value] : entries)
      kept.insertBack(i, column) = value;
  }
  kept.finalize();
  return kept;
}

MatrixView AggregationMultigrid::Level::view() const {
  return {rows, rows, static_cast<Index>(column.size()), start.data(), column.data(), value.data()};
}

void AggregationMultigrid::Level::begin(Index n) {
  rows = n;
  start.assign(1, 0);
  column.clear();
  value.clear();
}

void AggregationMultigrid::Level::size_vectors() {
  const auto n = static_cast<std::size_t>(rows);
  inverse_diagonal.assign(n, 0.0);  // 1 / a_ii, and 0 where a_ii = 0: that unknown stays put
  for (std::size_t i = 0; i < n; ++i) {
    for (auto k = static_cast<std::size_t>(start[i]); k < static_cast<std::size_t>(start[i + 1]);
         ++k) {
      if (static_cast<std::size_t>(column[k]) == i && value[k] != 0.0)
        inverse_diagonal[i] = 1.0 / value[k];
    }
  }
  x.resize(n);
  b.resize(n);
  r.resize(n);
}

void AggregationMultigrid::lump(const Matrix& a) {
  Level& level = levels_.front();
  level.begin(a.rows());
  for (Index i = 0; i < a.rows(); ++i) {
    lump_row(a, i, lumped_fraction_, row_entries_);
    for (const auto& [col, entry] : row_entries_)
      level.append(col, entry);
    level.end_row();
  }
}

// The three passes of Vanek et al. (1996): whole neighbourhoods that are still free become
// aggregates; the rest join an aggregate one of their strong neighbours is in; what is left
// groups with its free strong neighbours. An unknown that has no strong coupling and that no
// aggregate takes in (a row of p = 0 at a free surface, a wall row whose couplings are all
// weak) stays out of the coarse levels, kIsolated: the smoother alone treats it. Returns the
// number of aggregates.
int AggregationMultigrid::aggregate(Level& level) {
  const MatrixView a = level.view();
  std::vector<int>& of = level.aggregate;
  const Index n = a.rows();
  of.assign(static_cast<std::size_t>(n), kFree);
  for (Index i = 0; i < n; ++i) {
    bool isolated = true;
    for_each_strong(a, i, [&](Index) { isolated = false; });
    if (isolated)
      of[static_cast<std::size_t>(i)] = kIsolated;
  }
  int count = 0;
  for (Index i = 0; i < n; ++i) {
    bool free = of[static_cast<std::size_t>(i)] == kFree;
    for_each_strong(a, i, [&](Index j) { free = free && of[static_cast<std::size_t>(j)] < 0; });
    if (!free)
      continue;
    of[static_cast<std::size_t>(i)] = count;
    for_each_strong(a, i, [&](Index j) { of[static_cast<std::size_t>(j)] = count; });
    ++count;
  }
  joined_.assign(of.begin(), of.end());
  for (Index i = 0; i < n; ++i) {
    if (of[static_cast<std::size_t>(i)] != kFree)
      continue;
    for_each_strong(a, i, [&](Index j) {
      if (joined_[static_cast<std::size_t>(i)] < 0)
        joined_[static_cast<std::size_t>(i)] = std::max(of[static_cast<std::size_t>(j)], kFree);
    });
  }
  of.swap(joined_);
  for (Index i = 0; i < n; ++i) {
    if (of[static_cast<std::size_t>(i)] != kFree)
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
void AggregationMultigrid::galerkin(const Level& fine, int count, Level& coarse) {
  const MatrixView a = fine.view();
  const std::vector<int>& of = fine.aggregate;
  const auto coarse_count = static_cast<std::size_t>(count);
  first_.assign(coarse_count + 1, 0);
  for (const int coarse_unknown : of) {
    if (coarse_unknown >= 0)
      ++first_[static_cast<std::size_t>(coarse_unknown) + 1];
  }
  std::partial_sum(first_.begin(), first_.end(), first_.begin());
  members_.resize(static_cast<std::size_t>(first_.back()));
  next_.assign(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < of.size(); ++i) {
    if (of[i] >= 0)
      members_[static_cast<std::size_t>(next_[static_cast<std::size_t>(of[i])]++)] =
          static_cast<int>(i);
  }

  coarse.begin(count);
  slot_row_.assign(coarse_count, -1);  // the row whose entry `slot_` points at
  slot_.resize(coarse_count);
  for (std::size_t row = 0; row < coarse_count; ++row) {
    row_entries_.clear();
    for (int m = first_[row]; m < first_[row + 1]; ++m) {
      for (MatrixView::InnerIterator it(a, members_[static_cast<std::size_t>(m)]); it; ++it) {
        const int coarse_column = of[static_cast<std::size_t>(it.col())];
        if (coarse_column < 0)
          continue;
        const auto column = static_cast<std::size_t>(coarse_column);
        if (slot_row_[column] != static_cast<int>(row)) {
          slot_row_[column] = static_cast<int>(row);
          slot_[column] = row_entries_.size();
          row_entries_.emplace_back(static_cast<int>(column), it.value());
        } else {
          row_entries_[slot_[column]].second += it.value();
        }
      }
    }
    std::sort(row_entries_.begin(), row_entries_.end());
    for (const auto& [col, entry] : row_entries_)
      coarse.append(col, entry);
    coarse.end_row();
  }
}

AggregationMultigrid& AggregationMultigrid::compute(const Matrix& a) {
  if (levels_.empty())
    levels_.emplace_back();
  lump(a);
  level_count_ = 1;
  while (true) {
    Level& level = levels_[level_count_ - 1];
    level.size_vectors();
    const Index n = level.rows;
    if (n <= kCoarsestSize || level_count_ == kMaxLevels)
      break;
    const int count = aggregate(level);
    if (count == 0 || count >= n)
      break;
    if (levels_.size() == level_count_)
      levels_.emplace_back();
    galerkin(levels_[level_count_ - 1], count, levels_[level_count_]);
    ++level_count_;
  }
  factor_coarsest();
  return *this;
}

// A failed factorisation must not be solved with (Eigen's SparseLU reads past its arrays): the
// sweeps stand in, and BiCGSTAB judges whether the system itself can be solved.
void AggregationMultigrid::factor_coarsest() {
  const MatrixView a = levels_[level_count_ - 1].view();
  coarsest_ = Coarsest::jacobi;
  if (a.rows() <= kCoarsestSize) {
    if (dense_.factor(a))
      coarsest_ = Coarsest::dense;
    return;
  }
  if (a.rows() > kLargestDirectSize)
    return;
  sparse_ = std::make_unique<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
  sparse_->compute(Eigen::SparseMatrix<double>(a));
  if (sparse_->info() == Eigen::Success)
    coarsest_ = Coarsest::sparse;
}

// The coarsest level directly, or, when the aggregation stalled above kLargestDirectSize
// unknowns (a matrix without strong couplings) or the factorisation failed, by Jacobi sweeps.
void AggregationMultigrid::solve_coarsest(const Level& l) const {
  if (coarsest_ == Coarsest::dense) {
    dense_.solve(l.b.data(), l.x.data());
    return;
  }
  if (coarsest_ == Coarsest::sparse) {
    as_vector(l.x) = sparse_->solve(as_vector(l.b));
    return;
  }
  as_vector(l.x) = kJacobiWeight * as_vector(l.inverse_diagonal).cwiseProduct(as_vector(l.b));
  for (int sweep = 1; sweep < kStalledSweeps; ++sweep) {
    residual(l.view(), l.x, l.b, l.r);
    as_vector(l.x) += kJacobiWeight * as_vector(l.inverse_diagonal).cwiseProduct(as_vector(l.r));
  }
}

// One V-cycle on levels_[level] for its b, into its x.
void AggregationMultigrid::cycle(std::size_t level) const {
  const Level& l = levels_[level];
  if (level + 1 == level_count_) {
    solve_coarsest(l);
    return;
  }
  const MatrixView a = l.view();
  const Eigen::Map<const Vector> inverse_diagonal = as_vector(l.inverse_diagonal);
  as_vector(l.x) = kJacobiWeight * inverse_diagonal.cwiseProduct(as_vector(l.b));  // from x = 0
  residual(a, l.x, l.b, l.r);
  const Level& next = levels_[level + 1];
  std::fill(next.b.begin(), next.b.end(), 0.0);
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    if (l.aggregate[i] >= 0)
      next.b[static_cast<std::size_t>(l.aggregate[i])] += l.r[i];
  }
  cycle(level + 1);
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    if (l.aggregate[i] >= 0)
      l.x[i] += kOverCorrection * next.x[static_cast<std::size_t>(l.aggregate[i])];
  }
  residual(a, l.x, l.b, l.r);
  as_vector(l.x) += kJacobiWeight * inverse_diagonal.cwiseProduct(as_vector(l.r));
}

AggregationMultigrid::Vector AggregationMultigrid::solve(const Vector& b) const {
  Vector x(b.size());
  apply(b, x);
  return x;
}

void AggregationMultigrid::apply(const Vector& in, Vector& out) const {
  const Level& finest = levels_.front();
  as_vector(finest.b) = in;
  cycle(0);
  out = as_vector(finest.x);
}

}  // namespace partimix
