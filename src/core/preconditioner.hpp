#pragma once
// What core/bicgstab.hpp asks of a preconditioner M: out = M^-1 in, into a vector the caller
// keeps, so that applying it allocates nothing.
#include <Eigen/Core>

namespace partimix {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  virtual void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const = 0;
};

}  // namespace partimix
