// core/sparse_pattern.hpp: rows laid out from (column, term) pairs in any order, equal columns
// sharing a slot, each term told its slot.
#include <gtest/gtest.h>

#include "core/sparse_pattern.hpp"

namespace partimix {
namespace {

TEST(SparsePattern, SortsColumnsMergesEqualOnesAndTellsEachTermItsSlot) {
  SparsePattern pattern;
  std::vector<int> slots(4, -1);
  std::vector<std::pair<std::int64_t, int>> row0{{2, 0}, {0, 1}, {2, 2}, {1, 3}};
  pattern.add_row(row0, slots);
  EXPECT_EQ(slots, (std::vector<int>{2, 0, 2, 1}));
  std::vector<int> more(1, -1);
  std::vector<std::pair<std::int64_t, int>> row1{{1, 0}};
  pattern.add_row(row1, more);
  EXPECT_EQ(more[0], 3);
  std::vector<std::pair<std::int64_t, int>> row2{{0, 0}, {2, 1}};
  std::vector<int> last(2, -1);
  pattern.add_row(row2, last);
  EXPECT_EQ(last, (std::vector<int>{4, 5}));

  SparsePattern::Matrix matrix;
  pattern.apply(matrix);
  ASSERT_EQ(matrix.rows(), 3);
  EXPECT_EQ(matrix.nonZeros(), 6);
  matrix.valuePtr()[2] += 1.0;  // both terms of column 2 in row 0 land here
  matrix.valuePtr()[2] += 1.0;
  EXPECT_EQ(matrix.coeff(0, 2), 2.0);
  EXPECT_EQ(matrix.coeff(1, 1), 0.0);
  EXPECT_EQ(matrix.coeff(1, 0), 0.0);

  pattern.clear();
  EXPECT_EQ(pattern.rows(), 0u);
}

}  // namespace
}  // namespace partimix
