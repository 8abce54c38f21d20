#pragma once
// The outcome of one of the incompressible scheme's iterative solves (the pressure Poisson
// equation, the implicit viscosity), for the run to stop with a reason when one fails.
namespace partimix::sph {

struct LinearSolve {
  int iterations = 0;     // the most over the systems solved
  double residual = 0.0;  // the largest relative residual
  bool converged = true;
};

}  // namespace partimix::sph
