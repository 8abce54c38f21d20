#include "core/sparse_pattern.hpp"

#include <algorithm>

#include "core/sparse_storage.hpp"

namespace partimix {

void SparsePattern::clear() {
  outer_.assign(1, 0);
  inner_.clear();
}

void SparsePattern::add_row(std::vector<std::pair<std::int64_t, int>>& entries,
                            std::vector<int>& slots) {
  std::sort(entries.begin(), entries.end());
  for (std::size_t e = 0; e < entries.size(); ++e) {
    if (e == 0 || entries[e].first != entries[e - 1].first)
      inner_.push_back(static_cast<int>(entries[e].first));
    slots[static_cast<std::size_t>(entries[e].second)] = static_cast<int>(inner_.size()) - 1;
  }
  outer_.push_back(static_cast<int>(inner_.size()));
}

void SparsePattern::apply(Matrix& matrix) const {
  const auto n = static_cast<Eigen::Index>(rows());
  matrix.resize(n, n);
  resize_nonzeros_with_room(matrix, static_cast<Eigen::Index>(inner_.size()));
  std::copy(outer_.begin(), outer_.end(), matrix.outerIndexPtr());
  std::copy(inner_.begin(), inner_.end(), matrix.innerIndexPtr());
  std::fill(matrix.valuePtr(), matrix.valuePtr() + inner_.size(), 0.0);
}

}  // namespace partimix
