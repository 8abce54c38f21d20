#include "particles/health.hpp"

#include <omp.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

namespace partimix {
namespace {

std::string where(const ParticleStore& store, std::size_t i) {
  const Vec3& x = store.position()[i];
  return fmt::format("particle {} at ({:.6g}, {:.6g}, {:.6g})", store.id()[i], x.x(), x.y(), x.z());
}

template <class Field, class IsFinite>
std::optional<std::string> first_non_finite(const ParticleStore& store, const Field& field,
                                            IsFinite&& is_finite) {
  for (std::size_t i = 0; i < field.values.size(); ++i) {
    if (!is_finite(field.values[i])) {
      return fmt::format("{} has a non-finite {}", where(store, i), field.name);
    }
  }
  return std::nullopt;
}

// How many values in [begin, end) are not finite (all exponent bits set: an infinity or a NaN).
// An integer count, whose order of summing does not matter, so the loop vectorises as it is.
std::size_t count_non_finite(const double* begin, const double* end) {
  constexpr std::uint64_t kExponent = 0x7ff0000000000000ULL;
  std::size_t count = 0;
  for (const double* v = begin; v != end; ++v)
    count += (std::bit_cast<std::uint64_t>(*v) & kExponent) == kExponent;
  return count;
}

// Whether every value of every field is finite and every particle inside the domain: one pass,
// split between the threads, whose verdict is exact (only the search for the first bad particle
// below reads the fields one by one).
bool all_healthy(const ParticleStore& store, const Domain& domain) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "a vector field is 3 n doubles in a row");
  constexpr std::size_t kParallelFrom = 4096;
  const std::size_t n = store.size();
  std::size_t non_finite = 0;
  bool outside = false;
#pragma omp parallel reduction(+ : non_finite) reduction(|| : outside) if (n >= kParallelFrom)
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t begin = n * thread / threads;
    const std::size_t end = n * (thread + 1) / threads;
    for (const auto& field : store.scalar_fields())
      non_finite += count_non_finite(field.values.data() + begin, field.values.data() + end);
    for (const auto& field : store.vector_fields()) {
      const double* values = field.values.empty() ? nullptr : field.values.front().data();
      non_finite += count_non_finite(values + 3 * begin, values + 3 * end);
    }
    for (std::size_t i = begin; i < end; ++i)
      outside = outside || !domain.contains(store.position()[i]);
  }
  return non_finite == 0 && !outside;
}

}  // namespace

std::optional<std::string> find_bad_particle(const ParticleStore& store, const Domain& domain) {
  if (all_healthy(store, domain))
    return std::nullopt;
  for (const auto& field : store.scalar_fields()) {
    auto bad = first_non_finite(store, field, [](double v) { return std::isfinite(v); });
    if (bad)
      return bad;
  }
  for (const auto& field : store.vector_fields()) {
    auto bad = first_non_finite(store, field, [](const Vec3& v) { return v.allFinite(); });
    if (bad)
      return bad;
  }
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!domain.contains(store.position()[i])) {
      return where(store, i) + " left the domain";
    }
  }
  return std::nullopt;
}

}  // namespace partimix
