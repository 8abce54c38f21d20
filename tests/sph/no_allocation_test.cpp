// The hot loop must not allocate (DESIGN.md, "Data and speed"): after warm-up, solver steps,
// including neighbour-list builds, particle re-sorting and the Shepard filter, make no heap
// allocation. Counted by replacing the global operator new in this test program.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "app/simulation.hpp"
#include "validation/case_factory.hpp"

namespace {
std::atomic<long> allocations{0};
}

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}

void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace partimix {
namespace {

TEST(NoAllocation, SolverStepsDoNotAllocateAfterWarmUp) {
  io::Case c = testing_cases::dam_break_2d(0.146, 0.146 / 10.0);
  c.sph.density.shepard = true;
  c.sph.density.shepard_interval = 7;
  c.sph.sort_interval = 5;
  app::Simulation sim = app::build_simulation(c);
  for (int k = 0; k < 20; ++k)
    sim.solver->step(sim.solver->stable_dt());
  const long before = allocations.load();
  for (int k = 0; k < 40; ++k)
    sim.solver->step(sim.solver->stable_dt());
  EXPECT_EQ(allocations.load() - before, 0) << "heap allocations during 40 steps";
}

}  // namespace
}  // namespace partimix
