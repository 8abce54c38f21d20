// core/sparse_storage.hpp: a matrix whose count of entries creeps up is reallocated once per
// eighth of growth, not at each increase, and its entries are laid out as Eigen's own
// resizeNonZeros lays them out.
#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include "core/sparse_storage.hpp"

namespace partimix {
namespace {

using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

TEST(SparseStorage, GrowsWithAnEighthToSpare) {
  Matrix matrix(10, 10);
  resize_nonzeros_with_room(matrix, 800);
  EXPECT_EQ(matrix.data().size(), 800);
  EXPECT_EQ(matrix.data().allocatedSize(), 900);
  const double* storage = matrix.valuePtr();
  // A refill with 900 entries or fewer keeps the storage, as a refill after resize() does.
  for (Eigen::Index count = 801; count <= 900; ++count) {
    matrix.resize(10, 10);
    resize_nonzeros_with_room(matrix, count);
    EXPECT_EQ(matrix.data().size(), count);
    EXPECT_EQ(matrix.valuePtr(), storage);
  }
  resize_nonzeros_with_room(matrix, 901);
  EXPECT_EQ(matrix.data().allocatedSize(), 901 + 901 / 8);
}

TEST(SparseStorage, KeepsTheEntriesAlreadyThereWhenItGrows) {
  Matrix matrix(2, 2);
  resize_nonzeros_with_room(matrix, 2);
  matrix.valuePtr()[0] = 3.0;
  matrix.valuePtr()[1] = 4.0;
  resize_nonzeros_with_room(matrix, 40);
  EXPECT_EQ(matrix.valuePtr()[0], 3.0);
  EXPECT_EQ(matrix.valuePtr()[1], 4.0);
}

}  // namespace
}  // namespace partimix
