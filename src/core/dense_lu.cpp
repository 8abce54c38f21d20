#include "core/dense_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace partimix {

bool DenseLu::factor(const MatrixView& a) {
  n_ = a.rows();
  const auto n = static_cast<std::size_t>(n_);
  lu_.assign(n * n, 0.0);
  pivot_.resize(n);
  for (Eigen::Index i = 0; i < n_; ++i) {
    for (MatrixView::InnerIterator it(a, i); it; ++it)
      lu_[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(it.col())] = it.value();
  }
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t largest = k;
    for (std::size_t i = k + 1; i < n; ++i) {
      if (std::abs(lu_[i * n + k]) > std::abs(lu_[largest * n + k]))
        largest = i;
    }
    pivot_[k] = static_cast<Eigen::Index>(largest);
    if (lu_[largest * n + k] == 0.0)
      return false;
    if (largest != k)
      std::swap_ranges(lu_.begin() + static_cast<std::ptrdiff_t>(k * n),
                       lu_.begin() + static_cast<std::ptrdiff_t>((k + 1) * n),
                       lu_.begin() + static_cast<std::ptrdiff_t>(largest * n));
    const double* pivot_row = &lu_[k * n];
    for (std::size_t i = k + 1; i < n; ++i) {
      double* row = &lu_[i * n];
      const double factor = row[k] / pivot_row[k];
      row[k] = factor;
      if (factor == 0.0)
        continue;
      for (std::size_t j = k + 1; j < n; ++j)
        row[j] -= factor * pivot_row[j];
    }
  }
  return true;
}

void DenseLu::solve(const double* b, double* x) const {
  const auto n = static_cast<std::size_t>(n_);
  std::copy(b, b + n, x);
  for (std::size_t k = 0; k < n; ++k)
    std::swap(x[k], x[static_cast<std::size_t>(pivot_[k])]);
  for (std::size_t i = 1; i < n; ++i) {
    for (std::size_t j = 0; j < i; ++j)
      x[i] -= lu_[i * n + j] * x[j];
  }
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t j = i + 1; j < n; ++j)
      x[i] -= lu_[i * n + j] * x[j];
    x[i] /= lu_[i * n + i];
  }
}

}  // namespace partimix
