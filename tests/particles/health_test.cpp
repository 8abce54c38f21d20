// The run's health check (particles/health.hpp): on a store large enough to be checked on several
// threads, a healthy store passes, and each kind of fault, alone or beside another, is reported
// for the first bad particle in the order of the fields (scalar fields, then vector fields, then
// the domain), whatever the number of threads.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <limits>
#include <string>

#include "particles/health.hpp"

namespace partimix {
namespace {

constexpr std::size_t kCount = 10000;

struct HealthyStore {
  ParticleStore store;
  Field<double>& pressure = store.add_scalar("pressure", "Pa");
  Field<Vec3>& force = store.add_vector("force", "N");
  Domain domain;

  HealthyStore() {
    store.resize(kCount);
    for (std::size_t i = 0; i < kCount; ++i) {
      store.id()[i] = static_cast<std::int64_t>(i);
      store.position()[i] = Vec3(0.5, 0.5, static_cast<double>(i) / kCount);
      pressure.values[i] = -1e300 + 1e296 * static_cast<double>(i);  // large, finite
      force.values[i] = Vec3(1e300, -1e300, 0.0);
    }
  }
};

std::string report(const HealthyStore& healthy) {
  return find_bad_particle(healthy.store, healthy.domain).value_or("healthy");
}

void expect_report(const HealthyStore& healthy, const std::string& expected) {
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(report(healthy), expected) << threads << " threads";
  }
  omp_set_num_threads(1);
}

TEST(Health, AHealthyStorePasses) {
  const HealthyStore healthy;
  expect_report(healthy, "healthy");
}

TEST(Health, TheFirstBadParticleIsNamedInTheOrderOfTheFields) {
  HealthyStore healthy;
  healthy.store.position()[9000].x() = 1.5;
  expect_report(healthy, "particle 9000 at (1.5, 0.5, 0.9) left the domain");
  healthy.force.values[7001].z() = std::numeric_limits<double>::infinity();
  expect_report(healthy, "particle 7001 at (0.5, 0.5, 0.7001) has a non-finite force");
  healthy.pressure.values[8000] = std::numeric_limits<double>::quiet_NaN();
  healthy.pressure.values[6000] = -std::numeric_limits<double>::infinity();
  expect_report(healthy, "particle 6000 at (0.5, 0.5, 0.6) has a non-finite pressure");
}

}  // namespace
}  // namespace partimix
