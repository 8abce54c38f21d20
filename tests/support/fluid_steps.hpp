#pragma once
// Steps a grid fluid at its own stable step until `end` (tests of src/cfd); each step's solves
// must converge.
#include <gtest/gtest.h>

#include "cfd/fluid_solver.hpp"

namespace partimix::test_support {

inline void step_fluid_until(cfd::FluidSolver& fluid, double end) {
  for (double t = 0.0; t < end;) {
    const double dt = fluid.stable_dt();
    ASSERT_TRUE(fluid.step(dt).converged) << "at t = " << t;
    t += dt;
  }
}

}  // namespace partimix::test_support
