#include "sph/smoothing_length.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::sph {

namespace {

// A Newton step changes h by at most this factor either way.
constexpr double kLargestStep = 2.0;

struct Sums {
  double density = 0.0;       // sum_j m_j W(r_ij, h)
  double h_derivative = 0.0;  // sum_j m_j dW(r_ij, h)/dh
};

Sums sum_over_neighbours(const SmoothingLengthFields& f, std::size_t i, std::size_t count,
                         const CellGrid& grid, const ScaledKernel& kernel, double h) {
  Sums sums;
  const double reach2 = kernel.support() * kernel.support() * h * h;
  grid.for_each_neighbour(
      i, f.position,
      [&](std::size_t j, const Vec3&, double r2) {
        if (r2 >= reach2)
          return;
        const double r = std::sqrt(r2);
        sums.density += f.mass[j] * kernel.value(r, h);
        sums.h_derivative += f.mass[j] * kernel.h_derivative(r, h);
      },
      count);
  return sums;
}

double power(double x, int n) {
  double p = x;
  for (int k = 1; k < n; ++k)
    p *= x;
  return p;
}

// Newton's method on g(h) = sum_j m_j W(r_ij, h) - m_i (eta / h)^d; returns its iterations, or
// -1 when it did not converge or h reached `largest`.
int solve_particle(const SmoothingLengthSettings& s, const SmoothingLengthFields& f, std::size_t i,
                   std::size_t count, const CellGrid& grid, const ScaledKernel& kernel, int d,
                   double largest) {
  double h = std::min(f.h[i], largest);
  for (int iteration = 1; iteration <= s.max_iterations; ++iteration) {
    const Sums sums = sum_over_neighbours(f, i, count, grid, kernel, h);
    const double wanted = f.mass[i] * power(s.eta / h, d);
    const double slope = sums.h_derivative + d * wanted / h;
    double next = slope != 0.0 ? h - (sums.density - wanted) / slope : kLargestStep * h;
    next = std::clamp(next, h / kLargestStep, std::min(kLargestStep * h, largest));
    const bool converged = std::abs(next - h) <= s.tolerance * h;
    h = next;
    if (converged) {
      const Sums final_sums = sum_over_neighbours(f, i, count, grid, kernel, h);
      f.h[i] = h;
      f.density[i] = final_sums.density;
      f.omega[i] = 1.0 + h / (d * final_sums.density) * final_sums.h_derivative;
      return h < largest ? iteration : -1;
    }
  }
  f.h[i] = h;
  return -1;
}

}  // namespace

SmoothingLengthSolve solve_smoothing_lengths(const SmoothingLengthSettings& settings,
                                             const SmoothingLengthFields& fields, std::size_t count,
                                             const CellGrid& grid, const ScaledKernel& kernel,
                                             int dimensions) {
  const double largest = grid.radius() / kernel.support();
  int most = 0;
  std::size_t failed = 0;
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 256) reduction(max : most) reduction(+ : failed)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const int taken = solve_particle(settings, fields, static_cast<std::size_t>(ii), count, grid,
                                     kernel, dimensions, largest);
    if (taken < 0)
      ++failed;
    else
      most = std::max(most, taken);
  }
  return {most, failed};
}

}  // namespace partimix::sph
