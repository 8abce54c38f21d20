#pragma once
// The outcome of an iterative linear solve (core/bicgstab.hpp, core/conjugate_gradient.hpp):
// the incompressible scheme's pressure Poisson equation and implicit viscosity report it, for
// the run to stop with a reason when one fails.
namespace partimix {

struct LinearSolve {
  int iterations = 0;     // the most over the systems solved
  double residual = 0.0;  // the largest relative residual |b - A x| / |b|
  bool converged = true;
};

}  // namespace partimix
