#pragma once
// Reproducible random numbers for statistical tests.
#include <cstdint>
#include <random>

namespace partimix::test_support {

// Uniform in [0, 1) from the top 53 bits of a 64-bit Mersenne twister: the same sequence on
// every platform (std::uniform_real_distribution is not specified bit for bit).
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : engine_(seed) {}
  double operator()() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace partimix::test_support
