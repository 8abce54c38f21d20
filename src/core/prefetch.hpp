#pragma once
// Asks the CPU to fetch the cache lines of `bytes` bytes at `data` ahead of their use.
// Always inlined, on purpose: a function that does nothing but prefetch looks free of effects
// to GCC, which then drops the calls to it (found in the DEM pair loop, docs/performance.md).
#include <cstddef>
#include <cstdint>

namespace partimix {

constexpr std::uintptr_t kCacheLine = 64;

[[gnu::always_inline]] inline void prefetch_lines(const void* data, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  for (std::uintptr_t line = begin & ~(kCacheLine - 1); line < begin + bytes; line += kCacheLine)
    __builtin_prefetch(reinterpret_cast<const void*>(line));
}

}  // namespace partimix
