#pragma once
// The pattern of a compressed row-major matrix built row by row from (column, term) pairs, for
// systems whose pattern is fixed while their values change each step (the grid fluid's
// pressure and momentum systems, docs/cfd.md): equal columns of a row share one slot, and each
// term learns the slot its value goes to, so a step refills the values without searching.
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

namespace partimix {

class SparsePattern {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  void clear();
  // Appends a row: its entries (column, term), term an index into `slots`, which receives the
  // entry's slot in the matrix's values. The entries are sorted in place.
  void add_row(std::vector<std::pair<std::int64_t, int>>& entries, std::vector<int>& slots);
  // Gives `matrix` (rows x rows) this pattern, its values zero.
  void apply(Matrix& matrix) const;

  std::size_t rows() const { return outer_.size() - 1; }

 private:
  std::vector<int> outer_{0};
  std::vector<int> inner_;
};

}  // namespace partimix
