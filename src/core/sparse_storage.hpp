#pragma once
// Storage of a compressed sparse matrix refilled at every step (the incompressible scheme's
// pressure and viscosity matrices, docs/sph.md, "The pressure solve"). Eigen's resizeNonZeros
// grows the storage to the exact count asked for, so a matrix whose count of entries creeps up
// from step to step reallocated its whole storage (and had the system map fresh pages for it)
// at nearly every step; this grows it with an eighth to spare instead, a bound on the memory
// held beyond the need.
#include <Eigen/SparseCore>

namespace partimix {

template <class SparseMatrix>
void resize_nonzeros_with_room(SparseMatrix& matrix, Eigen::Index nonzeros) {
  if (matrix.data().allocatedSize() < nonzeros)
    matrix.data().reserve(nonzeros + nonzeros / 8 - matrix.data().size());
  matrix.resizeNonZeros(nonzeros);
}

}  // namespace partimix
