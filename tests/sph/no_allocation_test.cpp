// The hot loop must not allocate (DESIGN.md, "Data and speed"): after warm-up, solver steps,
// including neighbour-list builds, particle re-sorting and the Shepard filter, make no heap
// allocation. Counted at malloc, calloc and realloc, which this test program replaces, so that
// Eigen's allocations (std::malloc) count as well as operator new's; under the sanitizers,
// which replace malloc themselves, at operator new only.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "app/simulation.hpp"
#include "io/case.hpp"
#include "validation/case_factory.hpp"

namespace {
std::atomic<long> allocations{0};
}

#if PARTIMIX_SANITIZED
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
#else
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);

void* malloc(std::size_t size) noexcept {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
}
#endif

namespace partimix {
namespace {

long allocations_in_40_steps_after_warm_up(const io::Case& c) {
  app::Simulation sim = app::build_simulation(c);
  for (int k = 0; k < 20; ++k)
    sim.methods[0].solver->step(sim.methods[0].solver->stable_dt());
  const long before = allocations.load();
  for (int k = 0; k < 40; ++k)
    sim.methods[0].solver->step(sim.methods[0].solver->stable_dt());
  return allocations.load() - before;
}

io::Case dam_break() {
  io::Case c = testing_cases::dam_break_2d(0.146, 0.146 / 10.0);
  testing_cases::sph_of(c).config.density.shepard = true;
  testing_cases::sph_of(c).config.density.shepard_interval = 7;
  testing_cases::sph_of(c).config.sort_interval = 5;
  return c;
}

TEST(NoAllocation, SolverStepsDoNotAllocateAfterWarmUp) {
  EXPECT_EQ(allocations_in_40_steps_after_warm_up(dam_break()), 0);
}

// The variable smoothing length: each particle's h and kernel scales at every interaction.
TEST(NoAllocation, VariableSmoothingLengthStepsDoNotAllocate) {
  io::Case c = dam_break();
  testing_cases::sph_of(c).config.variable_smoothing_length = true;
  EXPECT_EQ(allocations_in_40_steps_after_warm_up(c), 0);
}

// A shear-thinning fluid: shear rates, viscosities and the stress-form viscous operator.
TEST(NoAllocation, NonNewtonianStressFormStepsDoNotAllocate) {
  io::Case c = dam_break();
  testing_cases::sph_of(c).fluid.rheology.model = "power_law";
  testing_cases::sph_of(c).fluid.rheology.consistency = 0.1;
  testing_cases::sph_of(c).fluid.rheology.flow_index = 0.5;
  testing_cases::sph_of(c).fluid.rheology.viscosity_max = 1.0;
  testing_cases::sph_of(c).config.viscous_operator = "stress";
  EXPECT_EQ(allocations_in_40_steps_after_warm_up(c), 0);
}

// A planetary impeller in the CMC fluid (the demo's case, coarser): moving bodies with their
// poses, velocities and accelerations updated every half step.
TEST(NoAllocation, PlanetaryMixerStepsDoNotAllocate) {
  const io::Case c = io::load_case(
      std::string(PARTIMIX_SOURCE_DIR) + "/cases/bohl_planetary_cmc.yaml", {"sph.spacing=0.009"});
  EXPECT_EQ(allocations_in_40_steps_after_warm_up(c), 0);
}

// The same mixer with the incompressible scheme (docs/sph.md, "Incompressible SPH"): the
// pressure solve and its multigrid, the implicit viscosity and particle shifting.
TEST(NoAllocation, IncompressibleStepsDoNotAllocate) {
  const io::Case c = io::load_case(
      std::string(PARTIMIX_SOURCE_DIR) + "/cases/bohl_planetary_cmc.yaml",
      {"sph.spacing=0.009", "sph.scheme=incompressible", "sph.viscosity_integration=implicit",
       "sph.viscosity_iterations=1", "sph.shifting.model=fickian"});
  EXPECT_EQ(allocations_in_40_steps_after_warm_up(c), 0);
}

// The gel droplet of the multi-material scheme (docs/multi-material-sph.md): three materials,
// surface tension, conduction and the shell's stress. The shell's yield stress A is set to 1 Pa
// so that every shell particle yields within the first steps and the return to yield (whose
// closure once allocated) runs in the steps counted; at the case's 0.5 MPa none yields for
// thousands of steps.
TEST(NoAllocation, MultiMaterialStepsDoNotAllocate) {
  const io::Case c =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/gel_droplet_2d.yaml",
                    {"sph.spacing=2.0e-5", "sph.materials[2].solid.johnson_cook.A=1"});
  EXPECT_EQ(allocations_in_40_steps_after_warm_up(c), 0);
}

}  // namespace
}  // namespace partimix
