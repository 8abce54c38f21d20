#pragma once
// The SPH sections of a loaded case, for the tests that look at what the loader read.
#include "io/case.hpp"
#include "sph/sph_section.hpp"

namespace partimix::test_support {

inline const sph::Config& sph_config(const io::Case& c) {
  return c.section<sph::SphSection>("sph").config;
}

inline const sph::FluidSpec& fluid_of(const io::Case& c) {
  return c.section<sph::SphSection>("sph").fluid;
}

}  // namespace partimix::test_support
